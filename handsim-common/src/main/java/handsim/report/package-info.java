/**
 * Results people look at and keep: PNG charts drawn with Java2D without a display ({@link
 * handsim.report.Plot}) and result files written atomically, leaving no half-written or temporary
 * file behind ({@link handsim.report.Outputs}), and wall times as progress lines give them
 * ({@link handsim.report.Durations}). Imports only {@code handsim.config} and Jackson.
 */
package handsim.report;
