/**
 * Runs of the arm+hand: the one step order every run uses ({@link handsim.task.ServoLoop}),
 * scripted scenarios, the catch-and-throw episodes, their observations, rewards and
 * termination.
 */
package handsim.task;
