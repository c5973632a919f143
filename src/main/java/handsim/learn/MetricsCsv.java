package handsim.learn;

import java.io.BufferedWriter;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@code metrics.csv}: one row per training episode ({@link EpisodeStats}), flushed as it comes
 * so that a killed run keeps its curve. Opening for a resumed run first drops the rows of
 * episodes played after the checkpoint (they will be played again).
 */
public final class MetricsCsv implements TrainingListener, Closeable {

    public static final String HEADER = "episode,total_steps,decisions,reward,average_reward,q0,critic_loss,actor_loss,"
            + "updates,terminal,sigma,wall_seconds";

    private final BufferedWriter out;

    private MetricsCsv(BufferedWriter out) {
        this.out = out;
    }

    /**
     * Opens {@code file} for appending, keeping the rows of the first {@code keepEpisodes}
     * episodes already there (0 for a fresh run) and writing the header if the file is new.
     */
    public static MetricsCsv open(Path file, long keepEpisodes) throws IOException {
        List<EpisodeStats> kept = new ArrayList<>();
        if (Files.exists(file)) {
            for (EpisodeStats s : read(file)) {
                if (s.episode() <= keepEpisodes) {
                    kept.add(s);
                }
            }
        }
        AtomicFiles.write(file, o -> {
            StringBuilder sb = new StringBuilder(HEADER).append('\n');
            kept.forEach(s -> sb.append(row(s)).append('\n'));
            o.write(sb.toString().getBytes(StandardCharsets.UTF_8));
        });
        return new MetricsCsv(Files.newBufferedWriter(file, StandardCharsets.UTF_8, StandardOpenOption.APPEND));
    }

    @Override
    public void onEpisode(EpisodeStats s) {
        try {
            out.write(row(s));
            out.newLine();
            out.flush();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write metrics", e);
        }
    }

    @Override
    public void close() throws IOException {
        out.close();
    }

    static String row(EpisodeStats s) {
        return String.format(Locale.ROOT, "%d,%d,%d,%s,%s,%s,%s,%s,%d,%b,%s,%.3f", s.episode(), s.totalSteps(),
                s.decisions(), num(s.reward()), num(s.averageReward()), num(s.q0()), num(s.criticLoss()),
                num(s.actorLoss()), s.updates(), s.terminal(), num(s.sigma()), s.wallSeconds());
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "" : Double.toString(v);
    }

    /** The rows of a metrics file (empty fields read as NaN). */
    public static List<EpisodeStats> read(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        if (lines.isEmpty() || !lines.get(0).equals(HEADER)) {
            throw new IOException(file + ": not a metrics file (first line must be the header " + HEADER + ")");
        }
        List<EpisodeStats> out = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",", -1);
            if (f.length != 12) {
                throw new IOException(file + ": line " + (i + 1) + " has " + f.length + " fields, expected 12");
            }
            try {
                out.add(new EpisodeStats(Long.parseLong(f[0]), Long.parseLong(f[1]), Integer.parseInt(f[2]), parse(f[3]),
                        parse(f[4]), parse(f[5]), parse(f[6]), parse(f[7]), Long.parseLong(f[8]),
                        Boolean.parseBoolean(f[9]), parse(f[10]), parse(f[11])));
            } catch (NumberFormatException e) {
                throw new IOException(file + ": line " + (i + 1) + ": " + e.getMessage(), e);
            }
        }
        return out;
    }

    private static double parse(String s) {
        return s.isEmpty() ? Double.NaN : Double.parseDouble(s);
    }
}
