/**
 * Running an optimisation study of the card sleights: an {@link handsim.cards.study.Objective}
 * (a trial: parameters in, objective values out), a search space read from JSON
 * ({@link handsim.cards.study.StudyConfig}) and a {@link handsim.cards.study.Study} that
 * suggests trials with {@code handsim.cards.tpe}, runs them on worker threads or a cluster's
 * executors ({@link handsim.cards.study.TrialExecutor}, {@link handsim.cards.study.RemoteTrials})
 * with results that depend on neither, keeps one JSON file per trial, resumes after a kill,
 * prints progress with an ETA and draws the optimisation history (thesis Fig. 4.9) and, for
 * several objectives, the Pareto front (Fig. 4.11).
 *
 * <p>A command runs one in a few lines:
 * <pre>
 * StudyConfig config = StudyConfig.load(configFile);
 * Study study = Study.openOrCreate(outDir, config, seed, provenance);   // resumes if outDir has one
 * study.run(trial -&gt; sleight.evaluate(trial), 89, workers, System.out);
 * TrialRecord best = study.best().orElseThrow();                        // best.json, history.png written
 * </pre>
 *
 * <p>Imports {@code handsim.cards.tpe}, {@code handsim.config}, {@code handsim.report},
 * {@code handsim.rollout} (the cluster's calls), Jackson and the JDK; no physics, learning,
 * viewer, command-line or cluster library.
 *
 * <p>Imports the other card packages, {@code handsim.config}, {@code handsim.report} and {@code
 * handsim.rollout} at most; nothing else of handsim.
 */
package handsim.cards.study;
