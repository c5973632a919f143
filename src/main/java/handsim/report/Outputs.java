package handsim.report;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.config.Json;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/** Writing result files atomically (a reader never sees half a file). */
public final class Outputs {

    private Outputs() {
    }

    public static void writeJson(Path file, JsonNode node) throws IOException {
        writeString(file, Json.pretty(node) + "\n");
    }

    public static void writeString(Path file, String text) throws IOException {
        Path abs = file.toAbsolutePath();
        Files.createDirectories(abs.getParent());
        Path tmp = abs.resolveSibling(abs.getFileName() + ".tmp");
        Files.writeString(tmp, text);
        Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
