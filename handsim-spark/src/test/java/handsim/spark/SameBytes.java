package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Byte-for-byte comparison of two runs' files, but for the wall times they measured (which no two
 * runs share, on one machine or many): a JSON line holding a time, {@code "seconds"}, {@code
 * "...Seconds"}, {@code "secondsPer..."} or {@code "wall_s"}, is left out of both; every other byte must match. Lock files
 * ({@link handsim.report.Locks}) are not compared: they name the process that holds the folder.
 */
final class SameBytes {

    private static final Pattern TIME = Pattern.compile("^\\s*\"(seconds|[a-z]+Seconds|secondsPer[A-Za-z]+|wall_s)\" : [-0-9.E]+,?$");

    private SameBytes() {
    }

    /** The file's text without its lines of wall time. */
    static String withoutTimes(Path f) throws IOException {
        StringBuilder s = new StringBuilder();
        for (String line : Files.readAllLines(f)) {
            if (!TIME.matcher(line).matches()) {
                s.append(line).append('\n');
            }
        }
        return s.toString();
    }

    /**
     * An evaluate JSON without the fields that describe the run rather than its results: its wall
     * time, its workers (none on a cluster) and its provenance (the command line, --master among it).
     */
    static String evaluateResults(Path f) throws IOException {
        com.fasterxml.jackson.databind.node.ObjectNode o = (com.fasterxml.jackson.databind.node.ObjectNode) handsim.config.Json.load(f).node();
        o.remove(List.of("wall_s", "workers", "provenance"));
        return handsim.config.Json.pretty(o);
    }

    /** Every file of {@code expected} (a folder, recursively) is in {@code actual} with the same bytes, times aside. */
    static int assertSameFiles(Path expected, Path actual, List<String> skipped) throws IOException {
        List<Path> files;
        try (Stream<Path> walk = Files.walk(expected)) {
            files = walk.filter(Files::isRegularFile).sorted().toList();
        }
        int compared = 0;
        for (Path f : files) {
            Path rel = expected.relativize(f);
            if (skipped.stream().anyMatch(rel.toString()::startsWith) || handsim.report.Locks.isLockFile(f.getFileName().toString())) {
                continue;
            }
            Path other = actual.resolve(rel);
            assertTrue(Files.exists(other), rel + " is missing from " + actual);
            if (rel.getFileName().toString().equals("steps.csv")) {
                // a card trial's steps.csv ends each row with the step's wall time split in three (assembly, contact, solve)
                assertEquals(withoutLastColumns(f, 3), withoutLastColumns(other, 3), rel + ": every column but the wall times");
            } else if (rel.toString().endsWith(".json")) {
                assertEquals(withoutTimes(f), withoutTimes(other), rel + ": every byte but the wall times");
            } else {
                assertEquals(-1L, Files.mismatch(f, other), rel + ": byte for byte");
            }
            compared++;
        }
        return compared;
    }

    /** The file's lines without their last {@code n} comma-separated columns. */
    private static java.util.List<String> withoutLastColumns(Path file, int n) throws java.io.IOException {
        return Files.readAllLines(file).stream().map(line -> {
            String kept = line;
            for (int k = 0; k < n && kept.lastIndexOf(',') >= 0; k++) {
                kept = kept.substring(0, kept.lastIndexOf(','));
            }
            return kept;
        }).toList();
    }
}
