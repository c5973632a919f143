package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The learner sees tasks only through Env: no physics engine, no viewer (STYLE.md layout). */
class PackageRulesTest {

    @Test
    void learnImportsNeitherOde4jNorLwjgl() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("src/main/java/handsim/learn"))) {
            List<String> offenders = files.filter(f -> {
                try {
                    String s = Files.readString(f);
                    return s.contains("import org.ode4j") || s.contains("import org.lwjgl");
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }).map(Path::toString).toList();
            assertEquals(List.of(), offenders);
        }
    }
}
