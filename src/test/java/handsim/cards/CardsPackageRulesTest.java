package handsim.cards;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The soft-body card simulator stands alone: no physics engine, learner or viewer in
 * handsim.cards (STYLE.md layout), and its sparse-solver libraries only in handsim.cards.linalg.
 */
class CardsPackageRulesTest {

    private static final Path ROOT = Path.of("src/main/java/handsim/cards");

    private static List<String> offenders(Path dir, String... forbidden) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            return files.filter(f -> f.toString().endsWith(".java")).filter(f -> {
                try {
                    String s = Files.readString(f);
                    for (String prefix : forbidden) {
                        if (s.contains("import " + prefix) || s.contains("import static " + prefix)) {
                            return true;
                        }
                    }
                    return false;
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }).map(Path::toString).sorted().toList();
        }
    }

    @Test
    void cardsImportNeitherOde4jNorDl4jNorLwjgl() throws IOException {
        assertEquals(List.of(), offenders(ROOT, "org.ode4j", "org.deeplearning4j", "org.nd4j", "org.lwjgl", "picocli",
                "handsim.sim", "handsim.learn", "handsim.viewer", "handsim.app"));
    }

    @Test
    void sparseSolverLibrariesStayInLinalg() throws IOException {
        try (Stream<Path> dirs = Files.list(ROOT)) {
            for (Path dir : dirs.filter(Files::isDirectory).filter(d -> !d.endsWith("linalg")).toList()) {
                assertEquals(List.of(), offenders(dir, "org.ojalgo", "edu.emory.mathcs.csparsej"), "in " + dir);
            }
        }
    }

    @Test
    void everyCardsPackageSaysWhatLivesThere() throws IOException {
        try (Stream<Path> dirs = Files.walk(ROOT)) {
            List<String> missing = dirs.filter(Files::isDirectory).filter(d -> !Files.exists(d.resolve("package-info.java")))
                    .map(Path::toString).toList();
            assertEquals(List.of(), missing);
        }
    }
}
