/**
 * Card sleights as functions of their bone trajectories ({@link handsim.cards.sleight.CardSleight},
 * built by name in {@link handsim.cards.sleight.Sleights}): Card Snapping (thesis 4.2.4,
 * {@link handsim.cards.sleight.SnapTrial}) and Double Lift (4.2.5, {@link
 * handsim.cards.sleight.LiftTrial}, its rested stack kept by {@link
 * handsim.cards.sleight.StackCheckpoint}), with what they share: the card and fingertip specs,
 * the pinch-then-move windows ({@link handsim.cards.sleight.BoneWindows}), the configs as read
 * and a trial's cost ({@link handsim.cards.sleight.TrialCost}); a sleight as a study's objective in
 * the form that travels to a cluster ({@link handsim.cards.sleight.SleightObjective}).
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.sleight;
