package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The DAgger run's dataset on disk: exact round trips, and what a kill leaves behind. */
@Tag("fast")
class DemonstrationSetTest {

    private static Dagger.Episode episode(int round, int index, int decisions) {
        List<Dagger.Visit> visits = new java.util.ArrayList<>();
        for (int d = 0; d < decisions; d++) {
            double[] label = d % 2 == 0 ? new double[] {0.1 * d, -1.0 / 3} : null; // odd decisions: no label found
            visits.add(new Dagger.Visit(new double[] {Math.PI * d, 1e-17, -d}, new double[] {0.25, Math.E / 10},
                    new Demonstration(label, d == 0, 1 + d, d % 2 == 0 ? 0.75 : 0)));
        }
        return new Dagger.Episode(new Dagger.Request(round, index, 11, 12, 10, true), visits);
    }

    @Test
    void episodesComeBackExactlyByRoundAndIndex(@TempDir Path dir) throws IOException {
        DemonstrationSet set = new DemonstrationSet(dir.resolve("d.csv"), 3, 2);
        assertTrue(set.read().isEmpty(), "no file yet");
        set.append(episode(0, 0, 3));
        set.append(episode(0, 1, 2));
        set.append(episode(1, 0, 1));
        var read = set.read();
        assertEquals(2, read.get(0).size());
        List<Dagger.Visit> v = read.get(0).get(0);
        assertEquals(3, v.size());
        assertArrayEquals(new double[] {Math.PI * 2, 1e-17, -2}, v.get(2).observation(), 0, "doubles written exactly");
        assertArrayEquals(new double[] {0.2, -1.0 / 3}, v.get(2).label().action(), 0);
        assertNull(v.get(1).label().action(), "a decision the teacher found nothing for");
        assertTrue(v.get(0).label().proposalSucceeded());
        assertEquals(3, v.get(2).label().tries());
        assertEquals(0.75, v.get(2).label().robustness());
        assertEquals(1, read.get(1).get(0).size());
        // no teacher told its trials: no trials file
        assertTrue(Files.notExists(set.trialsFile()));
        List<Demonstration.Trial> trials = List.of(new Demonstration.Trial(new double[] {0.5, -0.5}, false, -0.02, new double[] {1.5}),
                new Demonstration.Trial(new double[] {0.25, 0.125}, true, 1.5, new double[] {Double.NaN}));
        set = new DemonstrationSet(dir.resolve("d.csv"), 3, 2, List.of("turn"));
        set.append(new Dagger.Episode(new Dagger.Request(2, 0, 1, 2, 10, true), List.of(new Dagger.Visit(new double[3], new double[2],
                new Demonstration(new double[] {0.25, 0.125}, false, 2, 1, trials)))));
        assertEquals(List.of("round,episode,decision,trial,success,reward,action_0,action_1,turn", "2,0,0,0,false,-0.02,0.5,-0.5,1.5",
                "2,0,0,1,true,1.5,0.25,0.125,NaN"), Files.readAllLines(dir.resolve("d-trials.csv")), "one row per trial, in order");
    }

    @Test
    void anEpisodeCutShortByAKillIsDroppedOnlyWhenItIsTheLast(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("d.csv");
        DemonstrationSet set = new DemonstrationSet(file, 3, 2);
        set.append(episode(0, 0, 2));
        set.append(episode(0, 1, 3));
        List<String> lines = Files.readAllLines(file);
        // the kill came after the second episode's first full row and half its second
        String cut = String.join("\n", lines.subList(0, 4)) + "\n" + lines.get(4).substring(0, 20);
        Files.writeString(file, cut);
        var read = set.read();
        assertEquals(1, read.get(0).size(), "the cut episode is gone: " + read.get(0).keySet());
        assertEquals(2, read.get(0).get(0).size());
        // the same rows with a whole episode after them: not a kill's trace but a broken file
        Files.writeString(file, String.join("\n", lines.subList(0, 4)) + "\n" + String.join("\n", lines.subList(0, 3).subList(1, 3)) + "\n");
        IOException e = assertThrows(IOException.class, set::read);
        assertTrue(e.getMessage().contains("line 5"), e.getMessage());
    }

    @Test
    void sortedEpisodesAreTheBytesOfEpisodesWrittenInOrder(@TempDir Path dir) throws IOException {
        // workers (threads or a cluster's executors) finish a round's episodes in any order; once
        // sorted, the files must be those of the same episodes written in (round, episode) order
        List<Demonstration.Trial> trials = List.of(new Demonstration.Trial(new double[] {0.5, -0.5}, false, -0.02, new double[] {1.5}));
        List<Dagger.Episode> inOrder = List.of(episode(0, 0, 2), episode(0, 1, 3), episode(1, 0, 1), episode(1, 1, 2), episode(1, 2, 3))
                .stream().map(e -> new Dagger.Episode(e.request(), e.visits().stream().map(v -> new Dagger.Visit(v.observation(),
                        v.proposal(), new Demonstration(v.label().action(), v.label().proposalSucceeded(), v.label().tries(),
                                v.label().robustness(), trials))).toList())).toList();
        DemonstrationSet ordered = new DemonstrationSet(dir.resolve("a.csv"), 3, 2, List.of("turn"));
        for (Dagger.Episode e : inOrder) {
            ordered.append(e);
        }
        DemonstrationSet shuffled = new DemonstrationSet(dir.resolve("b.csv"), 3, 2, List.of("turn"));
        for (int i : new int[] {1, 0}) { // round 0 finished out of order, then sorted
            shuffled.append(inOrder.get(i));
        }
        shuffled.sortEpisodes();
        for (int i : new int[] {4, 2, 3}) {
            shuffled.append(inOrder.get(i));
        }
        assertTrue(Files.mismatch(ordered.file(), shuffled.file()) >= 0, "before sorting, the rows are in the order episodes finished");
        shuffled.sortEpisodes();
        assertEquals(-1L, Files.mismatch(ordered.file(), shuffled.file()), "the demonstrations byte for byte");
        assertEquals(-1L, Files.mismatch(ordered.trialsFile(), shuffled.trialsFile()), "the teacher's trials byte for byte");
        assertEquals(List.of(0, 1, 2), List.copyOf(shuffled.read().get(1).keySet()), "read back by episode");
    }
}
