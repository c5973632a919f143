/**
 * Results people look at and keep, and nothing of them lost: PNG charts drawn with Java2D without
 * a display ({@link handsim.report.Plot}); result files written through one writer, atomically,
 * leaving no half-written or temporary file behind ({@link handsim.report.Outputs}); one process
 * at a time in a folder ({@link handsim.report.Locks}); a clean stop on SIGTERM or SIGINT
 * ({@link handsim.report.Stop}); and wall times as progress lines give them ({@link
 * handsim.report.Durations}). Imports only {@code handsim.config} and Jackson.
 */
package handsim.report;
