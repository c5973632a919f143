package handsim.learn;

import handsim.report.Outputs;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * {@code metrics.csv}: one row per training episode ({@link EpisodeStats}), forced to disk as it comes
 * so that a killed run keeps its curve. Opening for a resumed run first drops the rows of
 * episodes played after the checkpoint (they will be played again) and a partial last row.
 */
public final class MetricsCsv implements TrainingListener, Closeable {

    public static final String HEADER = "episode,total_steps,decisions,reward,average_reward,q0,critic_loss,actor_loss,"
            + "updates,terminal,sigma,wall_seconds";
    private static final int FIELDS = 12;

    private final Path file;

    private MetricsCsv(Path file) {
        this.file = file;
    }

    /**
     * Opens {@code file} for appending, keeping the rows of the first {@code keepEpisodes}
     * episodes already there (0 for a fresh run) and writing the header if the file is new. A
     * partial last row (what a run killed while appending leaves) is dropped, and so are rows
     * missing before the kept ones, each with a line to {@code warnings}.
     */
    public static MetricsCsv open(Path file, long keepEpisodes, Consumer<String> warnings) throws IOException {
        List<EpisodeStats> kept = new ArrayList<>();
        if (Files.exists(file)) {
            for (EpisodeStats s : read(file, warnings)) {
                if (s.episode() <= keepEpisodes) {
                    kept.add(s);
                }
            }
        }
        if (kept.size() != keepEpisodes) {
            warnings.accept(file + " holds " + kept.size() + " rows of the " + keepEpisodes + " episodes played before the "
                    + "checkpoint: the learning curve lacks the others");
        }
        Outputs.write(file, o -> {
            StringBuilder sb = new StringBuilder(HEADER).append('\n');
            kept.forEach(s -> sb.append(row(s)).append('\n'));
            o.write(sb.toString().getBytes(StandardCharsets.UTF_8));
        });
        return new MetricsCsv(file);
    }

    /** {@link #open(Path, long, Consumer)} printing its warnings to standard error. */
    public static MetricsCsv open(Path file, long keepEpisodes) throws IOException {
        return open(file, keepEpisodes, w -> System.err.println("warning: " + w));
    }

    /** Appends the episode's row, forced to disk ({@link Outputs#append}). */
    @Override
    public void onEpisode(EpisodeStats s) {
        try {
            Outputs.append(file, (row(s) + "\n").getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Nothing to close: each row is written and forced as it comes. */
    @Override
    public void close() {
    }

    static String row(EpisodeStats s) {
        return String.format(Locale.ROOT, "%d,%d,%d,%s,%s,%s,%s,%s,%d,%b,%s,%.3f", s.episode(), s.totalSteps(),
                s.decisions(), num(s.reward()), num(s.averageReward()), num(s.q0()), num(s.criticLoss()),
                num(s.actorLoss()), s.updates(), s.terminal(), num(s.sigma()), s.wallSeconds());
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "" : Double.toString(v);
    }

    /** The rows of a metrics file (empty fields read as NaN); a damaged row fails with its line. */
    public static List<EpisodeStats> read(Path file) throws IOException {
        return read(file, null);
    }

    /**
     * The rows of a metrics file; with {@code warnings} not null a partial last row (one that
     * does not end the file with a line break, or has too few fields) is dropped and said there.
     */
    public static List<EpisodeStats> read(Path file, Consumer<String> warnings) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        List<String> lines = text.lines().toList();
        if (lines.isEmpty() || !lines.get(0).equals(HEADER)) {
            throw new IOException(file + ": not a metrics file (its first line must be the header " + HEADER + ")");
        }
        List<EpisodeStats> out = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            try {
                out.add(parseRow(lines.get(i)));
            } catch (IllegalArgumentException e) {
                boolean last = i == lines.size() - 1;
                if (warnings != null && last && (!text.endsWith("\n") || lines.get(i).split(",", -1).length < FIELDS)) {
                    warnings.accept(file + ": line " + (i + 1) + " is a partial row (a run stopped while writing it): dropped");
                    break;
                }
                throw new IOException(file + ": line " + (i + 1) + ": " + e.getMessage());
            }
        }
        return out;
    }

    private static EpisodeStats parseRow(String line) {
        String[] f = line.split(",", -1);
        if (f.length != FIELDS) {
            throw new IllegalArgumentException("has " + f.length + " fields, expected " + FIELDS);
        }
        return new EpisodeStats(Long.parseLong(f[0]), Long.parseLong(f[1]), Integer.parseInt(f[2]), parse(f[3]),
                parse(f[4]), parse(f[5]), parse(f[6]), parse(f[7]), Long.parseLong(f[8]), parseBoolean(f[9]), parse(f[10]),
                parse(f[11]));
    }

    private static boolean parseBoolean(String s) {
        if (!s.equals("true") && !s.equals("false")) {
            throw new IllegalArgumentException("terminal must be true or false, got \"" + s + "\"");
        }
        return s.equals("true");
    }

    private static double parse(String s) {
        return s.isEmpty() ? Double.NaN : Double.parseDouble(s);
    }
}
