package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Node, the npm packages of {@code scripts/gltf-viewer} and Debian's headless Chromium, for the
 * tests tagged {@code browser}: they fail with what to install when a tool is missing (the
 * suite can leave them out with {@code -DexcludedGroups=browser}).
 */
public final class WebTools {

    public static final Path VIEWER = Path.of("scripts/gltf-viewer").toAbsolutePath();
    /** How long a tool may take (s): a validation or a screenshot takes a few seconds. */
    static final long TIMEOUT_SECONDS = 120;

    private WebTools() {
    }

    /** Fails with what to install when node or the npm packages are missing. */
    public static void requireNode() {
        requireCommand("node", "node is not on PATH: install it (apt-get install nodejs npm), then npm ci in scripts/gltf-viewer "
                + "(.ci/run does both), or leave these tests out with -DexcludedGroups=browser");
        if (!Files.isDirectory(VIEWER.resolve("node_modules/three")) || !Files.isDirectory(VIEWER.resolve("node_modules/gltf-validator"))) {
            fail("scripts/gltf-viewer/node_modules lacks three or gltf-validator: run npm ci in scripts/gltf-viewer (.ci/run does), "
                    + "or leave these tests out with -DexcludedGroups=browser");
        }
    }

    /** The Chromium command; fails with what to install when there is none. */
    public static String requireChromium() {
        requireNode();
        for (String c : List.of("chromium", "chromium-browser")) {
            if (onPath(c)) {
                return c;
            }
        }
        fail("chromium is not on PATH: install Debian's (apt-get install chromium; .ci/run does), "
                + "or leave these tests out with -DexcludedGroups=browser");
        return null;
    }

    /** Runs {@code command} in {@code dir} and returns what it printed on stdout; fails on a non-zero exit. */
    public static String run(Path dir, List<String> command) throws IOException, InterruptedException {
        Path out = Files.createTempFile("handsim-web", ".out"), err = Files.createTempFile("handsim-web", ".err");
        try {
            Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            if (!p.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                fail(command.get(0) + " took over " + TIMEOUT_SECONDS + " s: " + String.join(" ", command));
            }
            String printed = Files.readString(out, StandardCharsets.UTF_8);
            assertEquals(0, p.exitValue(), String.join(" ", command) + "\n" + printed + Files.readString(err, StandardCharsets.UTF_8));
            return printed;
        } finally {
            Files.deleteIfExists(out);
            Files.deleteIfExists(err);
        }
    }

    /**
     * A screenshot of {@code scripts/gltf-viewer/index.html} with {@code query} (a still of the
     * animation), {@code width} x {@code height} pixels, by headless Chromium drawing WebGL
     * through SwiftShader.
     */
    public static Path screenshot(String query, int width, int height, Path png) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(requireChromium(), "--headless=new", "--no-sandbox", "--disable-gpu",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--allow-file-access-from-files", "--hide-scrollbars",
                "--virtual-time-budget=10000", "--window-size=" + width + "," + height, "--screenshot=" + png.toAbsolutePath(),
                VIEWER.resolve("index.html").toUri() + "?" + query + "&w=" + width + "&h=" + height));
        run(VIEWER, command);
        assertTrue(Files.size(png) > 0, "a screenshot");
        return png;
    }

    private static void requireCommand(String name, String message) {
        if (!onPath(name)) {
            fail(message);
        }
    }

    private static boolean onPath(String name) {
        String path = System.getenv("PATH");
        for (String dir : path == null ? new String[0] : path.split(java.io.File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, name))) {
                return true;
            }
        }
        return false;
    }
}
