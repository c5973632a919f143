package handsim.cards.study;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.tpe.CompletedTrial;
import handsim.cards.tpe.Direction;
import handsim.cards.tpe.Pareto;
import handsim.cards.tpe.TpeSampler;
import handsim.config.ConfigException;
import handsim.config.Json;
import handsim.report.Locks;
import handsim.report.Outputs;
import handsim.report.Stop;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * A TPE study of an {@link Objective} over a {@link StudyConfig}'s search space, kept in a
 * folder:
 * <pre>
 * study.json               config, seed, sampler, what the objective is, the provenance of every run
 * trials/trial-0007.json   one file per finished trial, written atomically
 * best.json                the best trial (one objective) or the Pareto front (several)
 * history.png              objective per trial and best so far (thesis Fig. 4.9);
 *                          history-NAME.png per objective when there are several
 * </pre>
 *
 * <p><b>Determinism.</b> Trial k's parameters depend on the seed, k and the trials numbered
 * 0 … k - P only (P = {@code parallelTrials} of the config):
 * <ul>
 *   <li>its random generator is seeded from the seed and k alone (the (k+1)-th long of a
 *       {@link SplittableRandom} seeded with the study's seed);</li>
 *   <li>it is suggested once every trial numbered 0 … k - P has finished, from those of them
 *       that completed, never from a later one that happens to have finished.</li>
 * </ul>
 * Trials start in number order on up to {@code workers} threads (or a cluster's executors:
 * {@link TrialExecutor}), at most P at a time. So the
 * study's trials are the same for any number of workers, and a study resumed after a kill
 * continues exactly as if it had never stopped: finished trials are read back bit for bit, and
 * a trial that was running is run again with the same parameters. P = 1 is Optuna's sequential
 * study; P &gt; 1 is Optuna with P parallel jobs in the case where each trial misses the P - 1
 * before it, fixed so that timing cannot change the result.
 */
public final class Study {

    public static final String STUDY_FILE = "study.json";
    public static final String TRIALS_DIR = "trials";
    public static final String BEST_FILE = "best.json";
    private static final Pattern TRIAL_FILE = Pattern.compile("trial-(\\d+)\\.json");
    private static final String FORMAT = "handsim cards study 1";
    /** How often a study waiting for a trial looks for a stop request (ms); every {@link TrialExecutor} waits so. */
    static final long STOP_POLL_MILLIS = 100;

    private final Path dir;
    private final StudyConfig config;
    private final long seed;
    private final TpeSampler sampler;
    private final ObjectNode studyJson;
    private double displayScale = 1;
    private String displayUnit = "";
    /** Finished trials (complete or failed) by number. */
    private final TreeMap<Integer, TrialRecord> finished = new TreeMap<>();
    /** Whether study.json records this run already ({@link #recordRun}). */
    private boolean runRecorded;

    private Study(Path dir, StudyConfig config, long seed, ObjectNode studyJson) {
        this.dir = dir;
        this.config = config;
        this.seed = seed;
        this.sampler = new TpeSampler(config.params(), config.directions(), config.sampler());
        this.studyJson = studyJson;
    }

    /**
     * Opens the study in {@code dir} to run it, holding the folder for this process alone
     * ({@link Locks}: a second process is refused at once): creates it when the folder has no
     * study.json, resumes it otherwise, which requires the same config and seed (else a
     * {@link ConfigException} naming the field), and trial files inside the search space. {@code provenance} (command line, commit, ...)
     * is recorded in study.json for this run.
     */
    public static Study openOrCreate(Path dir, StudyConfig config, long seed, ObjectNode provenance) throws IOException {
        return openOrCreate(dir, config, seed, Json.mapper().createObjectNode(), provenance);
    }

    /**
     * {@link #openOrCreate(Path, StudyConfig, long, ObjectNode)} for an objective described by
     * {@code objective} (say the sleight's scene, mesh and materials), recorded in study.json:
     * a resume requires the same description as well, since the trials found would not be the
     * ones this objective gives otherwise.
     */
    public static Study openOrCreate(Path dir, StudyConfig config, long seed, ObjectNode objective, ObjectNode provenance) throws IOException {
        Files.createDirectories(dir);
        Locks.holdFolder(dir, "the study folder " + dir, note -> System.out.println("handsim: " + note));
        Path file = dir.resolve(STUDY_FILE);
        Study study;
        if (Files.exists(file)) {
            study = open(dir);
            if (study.seed != seed) {
                throw new ConfigException(file + ": seed: the study was created with seed " + study.seed + ", not " + seed);
            }
            String difference = firstDifference(study.config.toJson(), config.toJson(), "config");
            if (difference == null) {
                JsonNode recorded = study.studyJson.get("objective");
                difference = firstDifference(recorded == null ? Json.mapper().createObjectNode() : recorded, objective, "objective");
            }
            if (difference != null) {
                throw new ConfigException(file + ": " + difference + " (a study resumes only with the config it was created with)");
            }
        } else {
            ObjectNode json = Json.mapper().createObjectNode();
            json.put("format", FORMAT);
            json.put("seed", seed);
            json.set("config", config.toJson());
            json.set("sampler", samplerDescription(config));
            if (!objective.isEmpty()) {
                json.set("objective", objective.deepCopy());
            }
            json.putArray("runs");
            study = new Study(dir, config, seed, json);
        }
        ObjectNode run = ((ArrayNode) study.studyJson.get("runs")).addObject();
        run.put("finishedBefore", study.finished.size());
        run.set("provenance", provenance.deepCopy());
        return study; // study.json is written when the study runs: a command that fails before (its hold) leaves nothing
    }

    /** Writes study.json with this run recorded, once, as the study starts its trials. */
    private void recordRun() throws IOException {
        if (!runRecorded) {
            writeJson(dir.resolve(STUDY_FILE), studyJson);
            runRecorded = true;
        }
    }

    /** Reads an existing study (its config, seed and finished trials) without running it. */
    public static Study open(Path dir) throws IOException {
        Path file = dir.resolve(STUDY_FILE);
        Json json = Json.load(file);
        String format = json.string("format");
        if (!format.equals(FORMAT)) {
            throw json.fieldError("format", "expected \"" + FORMAT + "\", got \"" + format + "\"");
        }
        StudyConfig config = StudyConfig.fromJson(file + " config", json.get("config").node());
        Study study = new Study(dir, config, json.longValue("seed"), (ObjectNode) json.node().deepCopy());
        Path trials = dir.resolve(TRIALS_DIR);
        if (Files.isDirectory(trials)) {
            try (Stream<Path> files = Files.list(trials)) {
                for (Path f : (Iterable<Path>) files.sorted()::iterator) {
                    Matcher m = TRIAL_FILE.matcher(f.getFileName().toString());
                    if (m.matches()) { // anything else (a temporary file left by a kill) is ignored
                        TrialRecord t = TrialRecord.fromJson(Json.load(f), config);
                        if (t.number() != Integer.parseInt(m.group(1))) {
                            throw new ConfigException(f + ": number: " + t.number() + " does not match the file name");
                        }
                        study.finished.put(t.number(), t);
                    }
                }
            }
        }
        return study;
    }

    private static ObjectNode samplerDescription(StudyConfig config) {
        ObjectNode s = Json.mapper().createObjectNode();
        s.put("algorithm", config.multiObjective() ? "MOTPE (Ozaki et al. 2020)" : "TPE (Bergstra et al. 2011)");
        s.put("semantics", config.sampler().multivariate() ? "Optuna 3.6.1 TPESampler, multivariate=True"
                : "Optuna 3.6.1 TPESampler, independent sampling (multivariate=False)");
        s.put("gamma", "min(ceil(0.1 n), 25)");
        s.put("weights", "1 below 25 trials; the oldest n - 25 ramp from 1/n to 1");
        s.put("trialRandom", "trial k: SplittableRandom seeded with the (k+1)-th nextLong of SplittableRandom(seed)");
        s.put("history", "trial k is suggested from the completed trials numbered <= k - parallelTrials");
        return s;
    }

    public Path dir() {
        return dir;
    }

    public StudyConfig config() {
        return config;
    }

    public long seed() {
        return seed;
    }

    /** The finished trials (complete and failed), in number order. */
    public List<TrialRecord> trials() {
        return List.copyOf(finished.values());
    }

    /** The complete trial of best value, the earliest of equals (one objective). */
    public Optional<TrialRecord> best() {
        if (config.multiObjective()) {
            throw new IllegalStateException("a study of " + config.objectives().size() + " objectives has a Pareto front, not one best trial");
        }
        Direction d = config.directions().get(0);
        return finished.values().stream().filter(TrialRecord::isComplete)
                .min(Comparator.comparingDouble((TrialRecord t) -> d == Direction.MAXIMIZE ? -t.values()[0] : t.values()[0]));
    }

    /**
     * The trial a study reports: among the complete trials (the Pareto front when there are
     * several objectives), the one closest to zero with each objective scaled by its tolerance
     * (unscaled where it has none), the earliest of equals; for one objective without a
     * tolerance, the best.
     */
    public Optional<TrialRecord> chosen() {
        if (!config.multiObjective() && !config.hasTolerance(0)) {
            return best();
        }
        List<TrialRecord> candidates = config.multiObjective() ? paretoFront()
                : finished.values().stream().filter(TrialRecord::isComplete).toList();
        return candidates.stream().min(Comparator.comparingDouble(t -> norm(config.scaled(t.values()))));
    }

    private static double norm(double[] v) {
        double s = 0;
        for (double x : v) {
            s += x * x;
        }
        return Math.sqrt(s);
    }

    /** The complete trials no other one dominates, in number order. */
    public List<TrialRecord> paretoFront() {
        List<CompletedTrial> complete = finished.values().stream().filter(TrialRecord::isComplete).map(TrialRecord::toCompleted).toList();
        return Pareto.front(complete, config.directions()).stream().map(t -> finished.get(t.number())).toList();
    }

    /**
     * Runs trials until trials 0 … nTrials - 1 have all finished, on {@code workers} threads of
     * this JVM ({@link ThreadTrials}); see {@link #run(TrialExecutor, int, PrintStream)}.
     */
    public void run(Objective objective, int nTrials, int workers, PrintStream progress) throws IOException, InterruptedException {
        if (workers < 1) {
            throw new IllegalArgumentException("workers: must be >= 1, got " + workers);
        }
        try (TrialExecutor threads = new ThreadTrials(objective, config, workers)) {
            run(threads, nTrials, progress);
        }
    }

    /**
     * {@link #run(Objective, int, int, PrintStream)} with the trials run by {@code executor} (this
     * JVM's threads, or a cluster's executors): the trials and their files are the same whatever
     * runs them. The executor is the caller's to close.
     */
    public void run(TrialExecutor executor, int nTrials, PrintStream progress) throws IOException, InterruptedException {
        if (nTrials < 1) {
            throw new IllegalArgumentException("trials: must be >= 1, got " + nTrials);
        }
        recordRun();
        Progress log = new Progress(progress, this, nTrials);
        log.start(executor.describe());
        TreeSet<Integer> running = new TreeSet<>();
        try (Stop.Watch watch = Stop.watch()) {
            TrialRecord last = null;
            while (true) {
                for (int k = nextToStart(nTrials, running); k >= 0 && running.size() < executor.slots() && !Stop.requested();
                        k = nextToStart(nTrials, running)) {
                    running.add(k);
                    executor.start(k, suggest(k));
                }
                if (last != null) {
                    log.finished(last, running.size());
                }
                if (running.isEmpty()) {
                    break;
                }
                last = executor.next();
                if (last == null) {
                    break; // a stop was requested: the trials under way are abandoned (they run again on resume)
                }
                running.remove(last.number());
                finished.put(last.number(), last);
                writeJson(trialFile(last.number()), last.toJson(config));
                writeBest();
            }
        } finally {
            writeReport();
        }
        Stop.check(finished.size() + " trials finished, kept in " + dir + " (the same command goes on from them)");
        log.end();
    }

    /** The lowest trial number not finished and not running, if every trial it waits for has finished; else -1. */
    private int nextToStart(int nTrials, TreeSet<Integer> running) {
        int k = 0;
        while (k < nTrials && (finished.containsKey(k) || running.contains(k))) {
            k++;
        }
        return k < nTrials && allFinishedThrough(k - config.parallelTrials()) ? k : -1;
    }

    private boolean allFinishedThrough(int last) {
        for (int j = 0; j <= last; j++) {
            if (!finished.containsKey(j)) {
                return false;
            }
        }
        return true;
    }

    /** Trial k's parameters, from the completed trials numbered <= k - parallelTrials and trial k's own generator. */
    double[] suggest(int k) {
        List<CompletedTrial> history = new ArrayList<>();
        for (TrialRecord t : finished.headMap(k - config.parallelTrials(), true).values()) {
            if (t.isComplete()) {
                history.add(t.toCompleted());
            }
        }
        return sampler.suggest(history, trialRandom(seed, k));
    }

    /** Trial k's generator: seeded with the (k+1)-th long of SplittableRandom(seed), so it depends on (seed, k) only. */
    static SplittableRandom trialRandom(long seed, int k) {
        SplittableRandom root = new SplittableRandom(seed);
        long s = 0;
        for (int i = 0; i <= k; i++) {
            s = root.nextLong();
        }
        return new SplittableRandom(s);
    }

    /**
     * Trial {@code number} of {@code objective} at {@code x}, timed: complete, or failed when the
     * objective throws or gives a value that is not finite. What every executor of trials runs.
     */
    static TrialRecord trial(Objective objective, StudyConfig config, int number, double[] x) {
        long t0 = System.nanoTime();
        Evaluation e;
        try {
            e = objective.evaluate(TrialParams.of(number, config, x));
        } catch (Stop.Stopped stopped) {
            throw stopped;
        } catch (Exception ex) {
            // a trial past its budget says why in its message; anything else is named by its class too
            String why = ex instanceof Objective.TrialFailed ? ex.getMessage() : ex.toString();
            return TrialRecord.failed(number, x, why, (System.nanoTime() - t0) * 1e-9);
        } catch (OutOfMemoryError oom) {
            // what the trial allocated is garbage once its stack is gone: the study goes on without it
            return TrialRecord.failed(number, x, "out of memory (" + oom.getMessage() + ")", (System.nanoTime() - t0) * 1e-9);
        }
        double seconds = (System.nanoTime() - t0) * 1e-9;
        double[] values = e.values();
        if (values.length != config.objectives().size()) {
            throw new IllegalStateException("the objective returned " + values.length + " values for the study's " + config.objectives().size()
                    + " objectives " + config.objectives());
        }
        for (int i = 0; i < values.length; i++) {
            if (!Double.isFinite(values[i])) {
                return TrialRecord.failed(number, x, config.objectives().get(i) + " is " + values[i], seconds);
            }
        }
        return TrialRecord.complete(number, x, e, seconds);
    }

    private Path trialFile(int number) {
        return dir.resolve(TRIALS_DIR).resolve(String.format(Locale.ROOT, "trial-%04d.json", number));
    }

    /**
     * Figures show the objectives multiplied by {@code scale} and labelled with {@code unit} (say
     * 1000 and "mm" for objectives in metres); by default as they are.
     */
    public Study displayObjectives(double scale, String unit) {
        this.displayScale = scale;
        this.displayUnit = unit;
        return this;
    }

    /** best.json, the history plots and, for several objectives, the Pareto front (pareto.png). */
    public void writeReport() throws IOException {
        writeBest();
        HistoryPlot.write(this);
        if (config.multiObjective() && finished.values().stream().anyMatch(TrialRecord::isComplete)) {
            ParetoPlot.write(this, displayScale, displayUnit);
        }
    }

    private void writeBest() throws IOException {
        ObjectNode root = Json.mapper().createObjectNode();
        root.put("finished", finished.size());
        root.put("complete", finished.values().stream().filter(TrialRecord::isComplete).count());
        if (config.multiObjective()) {
            ArrayNode front = root.putArray("paretoFront");
            for (TrialRecord t : paretoFront()) {
                front.add(t.toJson(config));
            }
        } else {
            best().ifPresent(t -> root.set("best", t.toJson(config)));
        }
        chosen().ifPresent(t -> root.set("chosen", t.toJson(config).put("meetsTolerances", config.meets(t.values()))));
        writeJson(dir.resolve(BEST_FILE), root);
    }

    /** Writes a JSON file atomically ({@link Outputs}), as it was always written (pretty, a line break at the end). */
    private static void writeJson(Path file, JsonNode node) throws IOException {
        Outputs.writeString(file, Json.pretty(node) + "\n");
    }

    /** The first place where two JSON trees differ, as "path: a vs b"; null if equal. */
    private static String firstDifference(JsonNode a, JsonNode b, String path) {
        if (a.isObject() && b.isObject()) {
            Map<String, JsonNode> fields = new LinkedHashMap<>();
            for (Iterator<String> it = a.fieldNames(); it.hasNext(); ) {
                fields.put(it.next(), null);
            }
            b.fieldNames().forEachRemaining(n -> fields.put(n, null));
            for (String name : fields.keySet()) {
                JsonNode x = a.get(name), y = b.get(name);
                if (x == null || y == null) {
                    return path + "." + name + ": " + x + " in the study, " + y + " given";
                }
                String d = firstDifference(x, y, path + "." + name);
                if (d != null) {
                    return d;
                }
            }
            return null;
        }
        if (a.isArray() && b.isArray() && a.size() == b.size()) {
            for (int i = 0; i < a.size(); i++) {
                String d = firstDifference(a.get(i), b.get(i), path + "[" + i + "]");
                if (d != null) {
                    return d;
                }
            }
            return null;
        }
        // a number is its value: 4000000 read back from study.json (an int) is the long it was written from
        boolean same = a.isNumber() && b.isNumber() ? a.decimalValue().compareTo(b.decimalValue()) == 0 : a.equals(b);
        return same ? null : path + ": " + a + " in the study, " + b + " given";
    }
}
