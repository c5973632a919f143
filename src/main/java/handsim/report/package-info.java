/** Results people look at: PNG charts drawn with Java2D, without a display. Depends on nothing of handsim. */
package handsim.report;
