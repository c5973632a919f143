/**
 * Results people look at, and how every result file is written: PNG charts drawn with Java2D
 * without a display ({@link handsim.report.Plot}), and atomic writes that leave no half-written
 * or temporary file behind ({@link handsim.report.Outputs}). Depends on nothing of handsim but
 * {@code handsim.config}'s JSON.
 */
package handsim.report;
