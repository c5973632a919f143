/**
 * Runs of the arm+hand: the one step order every run uses ({@link handsim.task.ServoLoop}),
 * scripted scenarios, the catch-and-throw episodes, their observations, rewards and
 * termination; the twin-world throw planner and the teacher that labels a learner's decisions in
 * the same twin ({@link handsim.task.ThrowTeacher}); and scenes to watch: {@link handsim.task.InteractiveScene} (snapshot, status,
 * goal, commands), offered by a {@link handsim.task.SceneCatalog} and switched by {@link
 * handsim.task.SwitchingScene}.
 */
package handsim.task;
