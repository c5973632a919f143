package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The export and the mesh builder read snapshots and the model only (their package-info): no
 * physics engine, no OpenGL, no viewer, no command line.
 */
class PackageRulesTest {

    static final List<String> FORBIDDEN = List.of("import org.ode4j", "import org.lwjgl", "import handsim.viewer", "import handsim.sim.ode",
            "import picocli", "import handsim.app");

    @Test
    void exportAndMeshImportNoEngineNoOpenGlNoViewer() throws IOException {
        for (String pkg : List.of("export", "mesh")) {
            try (Stream<Path> files = Files.list(Path.of("src/main/java/handsim", pkg))) {
                List<String> offenders = files.filter(f -> {
                    try {
                        String s = Files.readString(f);
                        return FORBIDDEN.stream().anyMatch(s::contains);
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                }).map(Path::toString).toList();
                assertEquals(List.of(), offenders);
            }
        }
    }
}
