package handsim.config;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Where handsim's data lives: the project directory holding {@code models/} and
 * {@code configs/}. The launcher sets {@code -Dhandsim.home}; tests and {@code mvn exec:java}
 * run from the project directory itself.
 */
public final class Home {

    private Home() {
    }

    public static Path root() {
        String prop = System.getProperty("handsim.home");
        Path root = Path.of(prop != null ? prop : "").toAbsolutePath();
        if (!Files.isDirectory(root.resolve("models")) || !Files.isDirectory(root.resolve("configs"))) {
            throw new ConfigException("cannot find models/ and configs/ under " + root
                    + " (run from the handsim directory or set -Dhandsim.home)");
        }
        return root;
    }

    /** A file under the project root, e.g. {@code resolve("configs/sim.json")}. */
    public static Path resolve(String relative) {
        return root().resolve(relative);
    }

    /** The default arm+hand model. */
    public static Path defaultModel() {
        return resolve("models/arm_hand.json");
    }
}
