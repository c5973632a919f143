/**
 * The Tree-structured Parzen Estimator (Bergstra et al. 2011) and its multi-objective form
 * MOTPE (Ozaki et al. 2020), the optimiser of the thesis' card sleights, with the semantics of
 * Optuna 3.6.1's {@code TPESampler}: {@link handsim.cards.tpe.TpeSampler} suggests a trial's
 * parameters ({@link handsim.cards.tpe.Param}) from the finished trials
 * ({@link handsim.cards.tpe.CompletedTrial}); the split of good and bad trials, the Parzen
 * estimators with truncated-normal kernels, hypervolumes and the hypervolume subset selection
 * live in package-private classes beside it.
 *
 * <p>Imports the JDK and commons-math3 (the error function) only: no handsim package, no
 * physics, learning or viewer library. Running a study (trial files, resuming, workers) is
 * {@code handsim.cards.study}.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.tpe;
