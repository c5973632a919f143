package handsim.app;

import handsim.config.Home;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Where a result came from: the git commit of the code that ran (and whether its tree had
 * changes), the command line, and every config, model and policy file read with its SHA-256.
 * The code is the launcher's project ({@code -Dhandsim.code}), which is not the home when
 * {@code HANDSIM_HOME} puts the configs and runs elsewhere.
 */
final class Provenance {

    private Provenance() {
    }

    /** The provenance of a result made by {@code scripts/handsim ARGS...}, after its inputs were read. */
    static com.fasterxml.jackson.databind.node.ObjectNode of(java.util.List<String> args) {
        return of(args, gitCommit());
    }

    /**
     * The same, with the {@code commit} ({@link #gitCommit}) read when the run began: a long run's
     * tree may be committed or changed before it ends, and its result is the code it began with.
     */
    static com.fasterxml.jackson.databind.node.ObjectNode of(java.util.List<String> args, String commit) {
        var o = com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.objectNode();
        o.put("commit", commit);
        o.put("command", "scripts/handsim " + String.join(" ", args));
        var files = o.putObject("files");
        handsim.config.ReadLog.files().forEach(files::put);
        return o;
    }

    /** The commit of the code that runs ({@link #gitCommit(Path)} of {@link #codeRoot}). */
    static String gitCommit() {
        return gitCommit(codeRoot());
    }

    /** The project whose code runs: the launcher's ({@code -Dhandsim.code}), else the home. */
    static Path codeRoot() {
        String code = System.getProperty("handsim.code");
        return code != null ? Path.of(code) : Home.root();
    }

    /** {@code <commit>} or {@code <commit>+changes} of the tree at {@code dir}; {@code unknown} without git or outside a repository. */
    static String gitCommit(Path dir) {
        String head = git(dir, "rev-parse", "HEAD");
        if (head == null) {
            return "unknown";
        }
        String status = git(dir, "status", "--porcelain", "--untracked-files=no");
        return status == null || status.isEmpty() ? head : head + "+changes";
    }

    private static String git(Path dir, String... args) {
        String[] cmd = new String[args.length + 3];
        cmd[0] = "git";
        cmd[1] = "-C";
        cmd[2] = dir.toString();
        System.arraycopy(args, 0, cmd, 3, args.length);
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            if (!p.waitFor(10, TimeUnit.SECONDS) || p.exitValue() != 0) {
                return null;
            }
            return out;
        } catch (IOException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }
}
