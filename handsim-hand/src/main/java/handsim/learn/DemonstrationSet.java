package handsim.learn;

import handsim.report.Outputs;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The aggregated dataset of a DAgger run on disk ({@code demonstrations.csv}): one row per
 * visited decision, written episode by episode as they finish, so that a run killed at any moment
 * keeps every finished episode (an episode cut short by the kill, the last in the file, is dropped
 * on reading). Columns: {@code round, episode, decision, decisions} (the episode's number of
 * decisions, so that a cut-short episode shows), {@code proposal_succeeded, tries, robustness, labelled}, the
 * observation {@code obs_i}, the learner's proposal {@code proposal_j} and the teacher's label
 * {@code label_j} (empty when it found none). Numbers are written exactly ({@link Double#toString}).
 * The teacher's trials, when it tells them, go beside it ({@link #trialsFile}): one row per
 * trial, {@code round, episode, decision, trial, success, reward, action_j} and the outcome measures
 * the set was made with, written just after
 * their episode's rows (a kill between the two loses the trials of that episode only).
 * Episodes finish in an order that depends on the workers (threads or a cluster's executors) and
 * their speed; once a round has all its episodes, {@link #sortEpisodes} puts both files in
 * (round, episode) order, so that their bytes depend on the run alone.
 */
public final class DemonstrationSet {

    private final Path file;
    private final int observationSize;
    private final int actionSize;
    private final List<String> outcomeNames;

    /** A set without trial outcomes. */
    public DemonstrationSet(Path file, int observationSize, int actionSize) {
        this(file, observationSize, actionSize, List.of());
    }

    /** A set whose trials carry the outcome measures {@code outcomeNames} (columns of the trials file, in order). */
    public DemonstrationSet(Path file, int observationSize, int actionSize, List<String> outcomeNames) {
        this.file = file;
        this.observationSize = observationSize;
        this.actionSize = actionSize;
        this.outcomeNames = List.copyOf(outcomeNames);
    }

    public Path file() {
        return file;
    }

    /** Where the teacher's trials go: {@code NAME-trials.csv} beside {@code NAME.csv}. */
    public Path trialsFile() {
        return file.resolveSibling(file.getFileName().toString().replaceFirst("\\.csv$", "") + "-trials.csv");
    }

    /** Appends a finished episode's decisions (the header first when the file is new) and flushes them to disk. */
    public synchronized void append(Dagger.Episode e) throws IOException {
        boolean fresh = !Files.exists(file) || Files.size(file) == 0;
        StringBuilder sb = new StringBuilder();
        if (fresh) {
            sb.append(header()).append('\n');
        }
        int d = 0;
        for (Dagger.Visit v : e.visits()) {
            Demonstration l = v.label();
            sb.append(e.request().round()).append(',').append(e.request().episode()).append(',').append(d++).append(',')
                    .append(e.visits().size()).append(',').append(l.proposalSucceeded()).append(',').append(l.tries()).append(',')
                    .append(l.robustness()).append(',').append(l.labelled());
            for (double x : v.observation()) {
                sb.append(',').append(x);
            }
            for (double x : v.proposal()) {
                sb.append(',').append(x);
            }
            for (int j = 0; j < actionSize; j++) {
                sb.append(',');
                if (l.labelled()) {
                    sb.append(l.action()[j]);
                }
            }
            sb.append('\n');
        }
        StringBuilder trials = new StringBuilder();
        if (!Files.exists(trialsFile()) || Files.size(trialsFile()) == 0) {
            trials.append("round,episode,decision,trial,success,reward");
            for (int j = 0; j < actionSize; j++) {
                trials.append(",action_").append(j);
            }
            outcomeNames.forEach(name -> trials.append(',').append(name));
            trials.append('\n');
        }
        int written = 0;
        for (int decision = 0; decision < e.visits().size(); decision++) {
            List<Demonstration.Trial> ts = e.visits().get(decision).label().trials();
            for (int t = 0; t < ts.size(); t++) {
                trials.append(e.request().round()).append(',').append(e.request().episode()).append(',').append(decision).append(',')
                        .append(t).append(',').append(ts.get(t).success()).append(',').append(ts.get(t).reward());
                for (double x : ts.get(t).action()) {
                    trials.append(',').append(x);
                }
                if (ts.get(t).outcome().length != outcomeNames.size()) {
                    throw new IllegalArgumentException("a trial has " + ts.get(t).outcome().length + " outcome measures, the set names "
                            + outcomeNames);
                }
                for (double x : ts.get(t).outcome()) {
                    trials.append(',').append(x);
                }
                trials.append('\n');
                written++;
            }
        }
        write(file, sb);
        if (written > 0) {
            write(trialsFile(), trials);
        }
    }

    /**
     * Rewrites both files with their rows in (round, episode) order, each episode's rows in the
     * order they were written (a stable sort), atomically ({@link Outputs}): the files of a run
     * are then the same whatever order its episodes finished in.
     */
    public synchronized void sortEpisodes() throws IOException {
        sortRows(file);
        sortRows(trialsFile());
    }

    private static void sortRows(Path f) throws IOException {
        if (!Files.exists(f)) {
            return;
        }
        List<String> lines = Files.readAllLines(f, StandardCharsets.UTF_8);
        if (lines.size() < 3) {
            return;
        }
        List<String> rows = new ArrayList<>(lines.subList(1, lines.size()));
        rows.sort(Comparator.comparingInt((String row) -> column(row, 0)).thenComparingInt(row -> column(row, 1)));
        Outputs.writeString(f, lines.get(0) + "\n" + String.join("\n", rows) + "\n");
    }

    /** Column {@code i} (0: round, 1: episode) of a row of either file. */
    private static int column(String row, int i) {
        return Integer.parseInt(row.split(",", 3)[i]);
    }

    /** Appends rows, forced to disk ({@link Outputs#append}). */
    private static void write(Path to, CharSequence text) throws IOException {
        Outputs.append(to, text.toString().getBytes(StandardCharsets.UTF_8));
    }

    private String header() {
        StringBuilder sb = new StringBuilder("round,episode,decision,decisions,proposal_succeeded,tries,robustness,labelled");
        for (int i = 0; i < observationSize; i++) {
            sb.append(",obs_").append(i);
        }
        for (int j = 0; j < actionSize; j++) {
            sb.append(",proposal_").append(j);
        }
        for (int j = 0; j < actionSize; j++) {
            sb.append(",label_").append(j);
        }
        return sb.toString();
    }

    /**
     * The episodes written so far, by round and then by episode index, each with its decisions
     * in order; empty when there is no file. An episode with fewer rows than its {@code decisions}
     * column, or a row of another width than the header's, is the trace of a kill and is dropped
     * when it is the last in the file; anywhere else it is an error naming the line.
     */
    public Map<Integer, Map<Integer, List<Dagger.Visit>>> read() throws IOException {
        Map<Integer, Map<Integer, List<Dagger.Visit>>> out = new LinkedHashMap<>();
        if (!Files.exists(file)) {
            return out;
        }
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        if (lines.isEmpty()) {
            return out;
        }
        if (!lines.get(0).equals(header())) {
            throw new IOException(file + ": the header does not match " + observationSize + " observation and " + actionSize
                    + " action entries");
        }
        int width = 8 + observationSize + 2 * actionSize;
        List<Dagger.Visit> episode = null;
        int expected = 0, round = -1, index = -1;
        for (int n = 1; n < lines.size(); n++) {
            String[] f = lines.get(n).split(",", -1);
            if (f.length != width) {
                if (n == lines.size() - 1) {
                    break; // cut short by a kill
                }
                throw new IOException(file + " line " + (n + 1) + ": " + f.length + " fields, expected " + width);
            }
            int decision = Integer.parseInt(f[2]);
            if (decision == 0) {
                if (episode != null && episode.size() != expected) {
                    throw new IOException(file + " line " + (n + 1) + ": the episode before has " + episode.size() + " of "
                            + expected + " decisions");
                }
                round = Integer.parseInt(f[0]);
                index = Integer.parseInt(f[1]);
                expected = Integer.parseInt(f[3]);
                episode = new ArrayList<>();
                out.computeIfAbsent(round, r -> new LinkedHashMap<>()).put(index, episode);
            }
            int at = 8;
            double[] obs = numbers(f, at, observationSize);
            at += observationSize;
            double[] proposal = numbers(f, at, actionSize);
            at += actionSize;
            boolean labelled = Boolean.parseBoolean(f[7]);
            Demonstration label = new Demonstration(labelled ? numbers(f, at, actionSize) : null, Boolean.parseBoolean(f[4]),
                    Integer.parseInt(f[5]), Double.parseDouble(f[6]));
            episode.add(new Dagger.Visit(obs, proposal, label));
        }
        if (episode != null && episode.size() != expected) {
            out.get(round).remove(index); // the last episode, cut short by a kill
        }
        return out;
    }

    private static double[] numbers(String[] f, int from, int n) {
        double[] x = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = Double.parseDouble(f[from + i]);
        }
        return x;
    }
}
