package handsim.evaluation;

import handsim.config.Home;
import handsim.config.ReadLog;
import handsim.rollout.RecordedTask;
import handsim.rollout.RolloutTask;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.function.Function;

import handsim.report.Outputs;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * The finished episodes of a long evaluation, one JSON line each, appended and flushed to disk
 * as each finishes: a run that is killed loses only the episodes under way, and the same
 * command run again reads the finished ones back instead of running them. The first line is
 * the run's signature (its options and the hashes of its inputs); a journal whose signature
 * differs belongs to another run and is refused, naming what differs. Each episode's line names
 * the commit of the code that ran it ({@link #episodesByCommit}): the signature holds the inputs,
 * not the code, so a run resumed after a commit says which episodes each commit ran. A line cut
 * short by a kill during its write is dropped on reading. Once the run's results are written the
 * journal is deleted.
 */
public final class EpisodeJournal {

    /** Episodes this run read back from the journal instead of running them. */
    private int readBack;

    private static final ObjectMapper MAPPER = new ObjectMapper();

    /** What an episode's line written without a commit counts under. */
    public static final String UNRECORDED = "unrecorded";

    private final Path file;
    private final String commit;
    /** A journaled episode: its result and the commit that ran it. */
    private record Entry(JsonNode result, String commit) {
    }

    private final Map<Integer, Entry> done;
    /** The episodes this run used (read back or ran): what {@link #episodesByCommit} counts. */
    private final Set<Integer> used = new HashSet<>();
    private final int droppedLines;

    private EpisodeJournal(Path file, String commit, Map<Integer, Entry> done, int droppedLines) {
        this.file = file;
        this.commit = Objects.requireNonNull(commit, "commit");
        this.done = done;
        this.droppedLines = droppedLines;
    }

    /**
     * The journal at {@code file}: the one a run with this {@code signature} left there, or a new
     * one; the episodes this run appends are written as run by {@code commit}. Throws {@link
     * IllegalArgumentException} if the file holds another run's journal.
     */
    public static EpisodeJournal open(Path file, ObjectNode signature, String commit) {
        try {
            if (!Files.exists(file)) {
                Files.createDirectories(file.toAbsolutePath().getParent());
                Outputs.writeString(file, MAPPER.writeValueAsString(header(signature)) + "\n");
                return new EpisodeJournal(file, commit, new HashMap<>(), 0);
            }
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            JsonNode head = lines.isEmpty() ? null : parse(lines.get(0)).orElse(null);
            if (head == null || !head.has("signature")) {
                throw new IllegalArgumentException(file + " is not an episode journal (delete it or write the results elsewhere)");
            }
            // compared as read back from text, as the journal's own is (a long written is an int read)
            String differs = difference(head.get("signature"), MAPPER.readTree(MAPPER.writeValueAsString(signature)), "");
            if (differs != null) {
                throw new IllegalArgumentException(file + " holds the finished episodes of another run (" + differs
                        + "): delete it to start afresh, or write the results elsewhere");
            }
            Map<Integer, Entry> done = new HashMap<>();
            int dropped = 0;
            for (String line : lines.subList(1, lines.size())) {
                Optional<JsonNode> entry = parse(line);
                if (entry.isPresent() && entry.get().has("index") && entry.get().has("result")) {
                    done.put(entry.get().get("index").asInt(),
                            new Entry(entry.get().get("result"), entry.get().path("commit").asText(UNRECORDED)));
                } else {
                    dropped++; // a write cut short by a kill
                }
            }
            return new EpisodeJournal(file, commit, done, dropped);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot use the episode journal " + file, e);
        }
    }

    private static ObjectNode header(ObjectNode signature) {
        ObjectNode h = JsonNodeFactory.instance.objectNode();
        h.set("signature", signature);
        return h;
    }

    private static Optional<JsonNode> parse(String line) {
        try {
            return Optional.ofNullable(MAPPER.readTree(line));
        } catch (JsonProcessingException e) {
            return Optional.empty();
        }
    }

    /** The first field where {@code was} and {@code is} differ (a dotted path and both values), or null if they are equal. */
    private static String difference(JsonNode was, JsonNode is, String at) {
        if (was.isObject() && is.isObject()) {
            List<String> names = new ArrayList<>();
            was.fieldNames().forEachRemaining(names::add);
            for (Iterator<String> it = is.fieldNames(); it.hasNext(); ) {
                String name = it.next();
                if (!was.has(name)) {
                    names.add(name);
                }
            }
            for (String name : names) {
                JsonNode a = was.path(name), b = is.path(name);
                String d = difference(a, b, at.isEmpty() ? name : at + "." + name);
                if (d != null) {
                    return d;
                }
            }
            return null;
        }
        return was.equals(is) ? null : at + " was " + was + ", is " + is;
    }

    /** The file this journal writes to. */
    public Path file() {
        return file;
    }

    /** The result journaled for episode {@code index}, if an interrupted run of the same command finished it. */
    public synchronized Optional<JsonNode> result(int index) {
        return Optional.ofNullable(done.get(index)).map(Entry::result);
    }

    /**
     * How many of the episodes this run used each commit ran (those it read back and those it
     * ran), by commit; {@link #UNRECORDED} for lines that name none. A journal line is one
     * rollout: an episode, or one copy's run of it for a sensitivity evaluation.
     */
    public synchronized SortedMap<String, Integer> episodesByCommit() {
        SortedMap<String, Integer> counts = new TreeMap<>();
        used.forEach(i -> counts.merge(done.get(i).commit(), 1, Integer::sum));
        return counts;
    }

    /** How many episodes interrupted runs of the same command finished. */
    public synchronized int finished() {
        return done.size();
    }

    /** Episodes this run read back from the journal instead of running them. */
    public synchronized int resumed() {
        return readBack;
    }

    /**
     * {@code task} that reads an episode back from this journal when an interrupted run of the
     * same command finished it, and otherwise runs it and journals its result at once (on a
     * cluster, the driver does both as results arrive: {@link RecordedTask}).
     */
    public <W, R> RecordedTask<W, R> resumable(RolloutTask<W, R> task, Function<R, JsonNode> write, Function<JsonNode, R> read) {
        return new RecordedTask<>(task, write, read, new RecordedTask.Journal() {
            @Override
            public Optional<JsonNode> finished(int index) {
                Optional<JsonNode> earlier = result(index);
                if (earlier.isPresent()) {
                    synchronized (EpisodeJournal.this) {
                        readBack++;
                        used.add(index);
                    }
                }
                return earlier;
            }

            @Override
            public void append(int index, JsonNode result) {
                EpisodeJournal.this.append(index, result);
            }
        });
    }

    /**
     * The SHA-256 of every file under configs/ and models/ and of {@code others} (those that
     * exist), by path: what a run's signature holds of its inputs.
     */
    public static SortedMap<String, String> inputHashes(List<Path> others) throws IOException {
        SortedMap<String, String> hashes = new TreeMap<>();
        for (String dir : List.of("configs", "models")) {
            try (var walk = Files.walk(Home.resolve(dir))) {
                for (Path f : walk.filter(Files::isRegularFile).toList()) {
                    hashes.put(Home.root().relativize(f).toString(), ReadLog.sha256(Files.readAllBytes(f)));
                }
            }
        }
        for (Path f : others) {
            if (f != null && Files.isRegularFile(f)) {
                hashes.put(f.toAbsolutePath().normalize().toString(), ReadLog.sha256(Files.readAllBytes(f)));
            }
        }
        return hashes;
    }

    /** Lines an interrupted run left unfinished (cut short by a kill) and that were dropped. */
    public int droppedLines() {
        return droppedLines;
    }

    /** Appends the result of episode {@code index} and forces it to disk before returning. */
    public synchronized void append(int index, JsonNode result) {
        ObjectNode entry = JsonNodeFactory.instance.objectNode().put("index", index).put("commit", commit);
        entry.set("result", result);
        try {
            // after a line cut short by a kill, start on a line of one's own
            byte[] line = ((Files.size(file) > 0 && !endsWithNewline()) ? "\n" : "").concat(MAPPER.writeValueAsString(entry) + "\n")
                    .getBytes(StandardCharsets.UTF_8);
            Outputs.append(file, line);
            done.put(index, new Entry(result, commit));
            used.add(index);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot append to the episode journal " + file, e);
        }
    }

    private boolean endsWithNewline() throws IOException {
        try (FileChannel in = FileChannel.open(file, StandardOpenOption.READ)) {
            java.nio.ByteBuffer last = java.nio.ByteBuffer.allocate(1);
            in.read(last, in.size() - 1);
            return last.get(0) == '\n';
        }
    }

    /** Deletes the journal: the run's results are written. */
    public void delete() {
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot delete the episode journal " + file, e);
        }
    }
}
