package handsim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.Home;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The project speaks of what it is and does, never of how or when it was developed. This test
 * scans every tracked text file (README, docs, code and test comments, configs, model and policy
 * files, scripts, CI) for the wording listed in {@code src/test/resources/history-wording/patterns.txt},
 * the one list of it, and fails naming file:line for each hit. The list is checked against
 * {@code readme-sample.md} beside it: lines of a README that narrated its history, each of which
 * must be flagged.
 */
@Tag("slow")
class HistoryWordingTest {

    static final String PATTERNS = "handsim-app/src/test/resources/history-wording/patterns.txt";
    static final String SAMPLE = "handsim-app/src/test/resources/history-wording/readme-sample.md";

    /** Files scanned: these endings, and everything under scripts/ and .ci/. */
    static final Set<String> TEXT_ENDINGS = Set.of(".md", ".java", ".json", ".txt", ".xml");

    @Test
    void noTrackedTextFileNarratesHowTheProjectWasDeveloped() throws IOException {
        Scanner scanner = Scanner.load(Home.resolve(PATTERNS));
        List<String> hits = new ArrayList<>();
        for (String file : textFiles(Home.root())) {
            Path path = Home.resolve(file);
            if (Files.isRegularFile(path)) {
                hits.addAll(scanner.scan(file, Files.readAllLines(path, StandardCharsets.UTF_8)));
            }
        }
        assertTrue(hits.isEmpty(), hits.size() + " lines tell how the project was developed "
                + "(say what it is and does; patterns in " + PATTERNS + "):\n" + String.join("\n", hits));
    }

    @Test
    void everyLineOfTheSampleReadmeIsFlagged() throws IOException {
        Scanner scanner = Scanner.load(Home.resolve(PATTERNS));
        List<String> lines = Files.readAllLines(Home.resolve(SAMPLE), StandardCharsets.UTF_8);
        assertTrue(lines.size() >= 10, "the sample holds at least 10 lines, got " + lines.size());
        for (int i = 0; i < lines.size(); i++) {
            List<String> hits = scanner.scan(SAMPLE, List.of(lines.get(i)));
            assertEquals(1, hits.size(), "line " + (i + 1) + " of the sample is flagged: " + lines.get(i));
        }
    }

    @Test
    void featureNamesAndOrdinaryWordsPass() throws IOException {
        Scanner scanner = Scanner.load(Home.resolve(PATTERNS));
        List<String> clean = List.of(
                "scripts/handsim train --resume RUN --session-episodes 200",
                "      --session-episodes=*) session_episodes=(\"${args[i]}\") ;;",
                "    long sessionEpisodes;",
                "final class ViewerSession implements AutoCloseable {",
                "a new random target apex every throw; the object's state now (sec. 3.6)",
                "the seeded distribution of throws used to start episodes",
                "run folder flip__flip-lying3k__1__20261123-233858, episode 3000",
                "a round after the first begins only when no earlier try succeeded");
        assertEquals(List.of(), scanner.scan("example", clean), "feature names and ordinary uses are not flagged");
    }

    @Test
    void aHitNamesTheFileTheLineAndTheWords() throws IOException {
        Scanner scanner = Scanner.load(Home.resolve(PATTERNS));
        String flagged = Files.readAllLines(Home.resolve(SAMPLE), StandardCharsets.UTF_8).get(0);
        List<String> hits = scanner.scan("docs/x.md", List.of("a line that says what handsim does", flagged));
        assertEquals(1, hits.size(), "one line flagged: " + hits);
        assertTrue(hits.get(0).startsWith("docs/x.md:2: \""), "file:line, then the words found: " + hits.get(0));
        assertTrue(hits.get(0).contains(" | " + flagged.strip().substring(0, 40)), "then the line: " + hits.get(0));
    }

    /**
     * The tracked files to scan, relative to {@code root}: {@code git ls-files} in a git checkout,
     * else every file under it (build output, run folders and dot folders other than .ci left out).
     * The pattern list and its sample are left out: they hold the wording on purpose.
     */
    static List<String> textFiles(Path root) throws IOException {
        List<String> files = gitLsFiles(root);
        if (files == null) {
            try (Stream<Path> walk = Files.walk(root)) {
                files = walk.filter(Files::isRegularFile).map(p -> root.relativize(p).toString().replace('\\', '/'))
                        .filter(f -> !f.startsWith("target/") && !f.contains("/target/") && !f.startsWith("runs/")
                                && !(f.startsWith(".") && !f.startsWith(".ci/")) && !f.contains("/."))
                        .collect(Collectors.toList());
            }
        }
        return files.stream().filter(HistoryWordingTest::isText)
                .filter(f -> !f.equals(PATTERNS) && !f.equals(SAMPLE)).sorted().collect(Collectors.toList());
    }

    static boolean isText(String file) {
        if (file.startsWith("scripts/") || file.startsWith(".ci/")) {
            return true;
        }
        int dot = file.lastIndexOf('.');
        return dot >= 0 && TEXT_ENDINGS.contains(file.substring(dot));
    }

    /** The files git tracks under {@code root}, or null when it is no git checkout or git is missing. */
    static List<String> gitLsFiles(Path root) {
        try {
            Process p = new ProcessBuilder("git", "ls-files", "-z").directory(root.toFile())
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0 || out.isEmpty()) {
                return null;
            }
            return Stream.of(out.split("\0")).filter(s -> !s.isEmpty()).collect(Collectors.toList());
        } catch (IOException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    /** The deny and allow lists of {@code patterns.txt}. */
    record Scanner(List<Pattern> deny, List<String> allow) {

        static Scanner load(Path file) {
            List<Pattern> deny = new ArrayList<>();
            List<String> allow = new ArrayList<>();
            try {
                for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                    if (line.startsWith("deny ")) {
                        deny.add(Pattern.compile(line.substring(5).strip(), Pattern.CASE_INSENSITIVE | Pattern.UNICODE_CASE));
                    } else if (line.startsWith("allow ")) {
                        allow.add(line.substring(6).strip());
                    } else if (!line.isBlank() && !line.startsWith("#")) {
                        throw new IllegalArgumentException(file + ": a line is a comment, 'deny REGEX' or 'allow TEXT', got: " + line);
                    }
                }
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            if (deny.isEmpty()) {
                throw new IllegalArgumentException(file + ": no deny patterns");
            }
            return new Scanner(List.copyOf(deny), List.copyOf(allow));
        }

        /** One entry "file:line: words found | the line" for each line that matches a deny pattern. */
        List<String> scan(String file, List<String> lines) {
            List<String> hits = new ArrayList<>();
            for (int i = 0; i < lines.size(); i++) {
                String line = lines.get(i);
                for (String a : allow) {
                    line = line.replace(a, " ".repeat(a.length()));
                }
                List<String> found = new ArrayList<>();
                for (Pattern p : deny) {
                    Matcher m = p.matcher(line);
                    while (m.find()) {
                        found.add("\"" + m.group() + "\"");
                    }
                }
                if (!found.isEmpty()) {
                    String text = lines.get(i).strip();
                    hits.add(file + ":" + (i + 1) + ": " + String.join(", ", found) + " | "
                            + (text.length() > 160 ? text.substring(0, 160) + "..." : text));
                }
            }
            return hits;
        }
    }
}
