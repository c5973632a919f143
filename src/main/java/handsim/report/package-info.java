/**
 * Results people look at and keep: PNG charts drawn with Java2D without a display, result files
 * written atomically, leaving no half-written or temporary file behind ({@link
 * handsim.report.Outputs}), and the journal of a long evaluation's finished episodes. Imports only
 * {@code handsim.config} (JSON).
 */
package handsim.report;
