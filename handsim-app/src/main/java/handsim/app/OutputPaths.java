package handsim.app;

import handsim.config.Home;
import handsim.report.Locks;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.ParseResult;

/**
 * The one check of a command's output paths, before any work starts. Every file and folder the
 * command will write is declared here, and each must be:
 * <ul>
 *   <li>not an input of the run: not a file another option names ({@code evaluate --policy P
 *       --json P}), nor one the command declares it reads ({@link #input}), nor anything under
 *       the project's {@code models/} and {@code configs/};</li>
 *   <li>not another output of the run ({@code --csv F --json F});</li>
 *   <li>a plain file where a file is written, a folder where a folder is, of a name the file
 *       system takes (at most 255 bytes, less what the atomic write's temporary name adds);</li>
 *   <li>writable: its folder is created, or shown writable by creating and deleting a probe
 *       file named as long as the write's temporary file.</li>
 * </ul>
 * The first problem fails with one line naming the option, the path and the reason ({@link
 * IllegalArgumentException}: exit status 2); nothing is created until every path passed. Then
 * the folders are created and the ones declared held ({@link #heldFolder}, {@link #heldFile})
 * are locked for this process ({@link Locks}): a second process is refused at once.
 *
 * <p>A command run ({@link Main#run}) is bracketed by {@link #begin}, which notes the paths its
 * options name, and {@link #end}, which releases the locks and, when the command failed, removes
 * the folders the checks created that it left empty.
 *
 * <pre>
 * new OutputPaths().file("--json", json).file("--csv", csv).heldFolder("--out", dir, "summary.json").check();
 * </pre>
 */
final class OutputPaths {

    /** The longest name a file system takes (bytes), and what an atomic write's temporary name adds to it. */
    private static final int NAME_MAX = 255, TEMPORARY_NAME_EXTRA = 28, PATH_MAX = 4095;

    private record Wanted(String option, Path path, boolean isFolder, boolean held, List<String> inside) {
        String label() {
            return option + " " + path;
        }
    }

    // ---- the command run: the paths its options name, what it declared, what the checks created ----
    /** The paths the command line names, each with its option (one path may be named by several). */
    private static final List<Map.Entry<Path, String>> OPTION_PATHS = new ArrayList<>();
    /** The inputs no option names, each with what it is in words. */
    private static final Map<Path, String> DECLARED_INPUTS = new LinkedHashMap<>();
    private static final Map<Path, String> OUTPUTS = new LinkedHashMap<>();
    /** Options that name outputs: handsim's commands name every output path with one of these, or declare it here. */
    private static final List<String> OUTPUT_OPTIONS = new ArrayList<>();
    private static final List<String> OUTPUT_OPTION_NAMES = List.of("--json", "--csv", "--plot", "--out", "--export", "--screenshot",
            "--runs");
    private static final List<Path> CREATED = new ArrayList<>();

    private final List<Wanted> wanted = new ArrayList<>();

    /**
     * What each command holds for itself alone while it runs, by option ({@code /}: a folder): held
     * as the process starts when it exists already ({@link #holdEarly}), so that a second process
     * on it is refused before it loads anything; by the command's own check otherwise.
     */
    private static final Map<String, List<String>> HELD = Map.of("demo", List.of("--out/"), "evaluate", List.of("--json"),
            "cards snap", List.of("--out/"), "cards lift", List.of("--out/"), "cards optimize", List.of("--out/"),
            "cards robust", List.of("--study/"), "train", List.of("--resume/"),
            "dagger", List.of("--resume/"));

    /** Starts a command run: every path its options and parameters name is an input unless declared an output. */
    static synchronized void begin(ParseResult parsed) {
        OPTION_PATHS.clear();
        DECLARED_INPUTS.clear();
        OUTPUTS.clear();
        OUTPUT_OPTIONS.clear();
        for (ParseResult p = parsed; p != null; p = p.subcommand()) {
            List<ArgSpec> args = new ArrayList<>(p.matchedOptions());
            args.addAll(p.matchedPositionals());
            for (ArgSpec a : args) {
                String name = a instanceof CommandLine.Model.OptionSpec o ? o.longestName() : a.paramLabel();
                Object v = a.getValue();
                if (v instanceof Path path) {
                    OPTION_PATHS.add(Map.entry(path.toAbsolutePath().normalize(), name));
                } else if (v instanceof Collection<?> values) {
                    values.stream().filter(Path.class::isInstance)
                            .forEach(path -> OPTION_PATHS.add(Map.entry(((Path) path).toAbsolutePath().normalize(), name)));
                }
            }
        }
    }

    /**
     * Holds what the command line {@code args} asks a command to hold ({@link #HELD}) when it
     * exists already, before the command line is parsed in full: the words before the first
     * option name the command, {@code --opt value} or {@code --opt=value} the path.
     *
     * @throws Locks.Held when another process holds it
     */
    static synchronized void holdEarly(String... args) {
        CREATED.clear();
        List<String> words = new ArrayList<>();
        for (int i = 0; i < args.length && !args[i].startsWith("-"); i++) {
            words.add(args[i]);
        }
        for (int n = words.size(); n > 0; n--) {
            List<String> held = HELD.get(String.join(" ", words.subList(0, n)));
            if (held != null) {
                held.forEach(h -> holdEarly(args, h));
                return;
            }
        }
    }

    private static void holdEarly(String[] args, String held) {
        boolean folder = held.endsWith("/");
        String option = folder ? held.substring(0, held.length() - 1) : held;
        String value = null;
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals(option) && i + 1 < args.length) {
                value = args[i + 1];
            } else if (args[i].startsWith(option + "=")) {
                value = args[i].substring(option.length() + 1);
            }
        }
        Path p;
        try {
            p = value == null ? null : Path.of(value).toAbsolutePath().normalize();
        } catch (InvalidPathException e) {
            return; // the command's own check says what is wrong with it
        }
        if (p == null) {
            return;
        }
        try {
            if (folder && Files.isDirectory(p)) {
                Locks.holdFolder(p, option + " " + p, note -> System.out.println("handsim: " + note));
            } else if (!folder && p.getParent() != null && Files.isDirectory(p.getParent())
                    && (!Files.exists(p) || Files.isRegularFile(p))) {
                Locks.holdFile(p, option + " " + p, note -> System.out.println("handsim: " + note));
            }
        } catch (Locks.Held inUse) {
            throw inUse;
        } catch (IllegalArgumentException cannotLock) {
            // a path that cannot take a lock file (a name too long, a folder not writable): the command's check says why
        }
    }

    /**
     * Ends a command run: releases what it holds and, if it {@code failed}, removes the folders
     * its checks created that it left empty (a refused or failed command leaves nothing behind).
     */
    static synchronized void end(boolean failed) {
        Locks.releaseAll();
        if (failed) {
            for (int i = CREATED.size() - 1; i >= 0; i--) {
                RunFolders.release(CREATED.get(i));
            }
        }
        CREATED.clear();
    }

    /** Declares a file the command reads that no option names (a run folder's metrics.csv): no output may be it. */
    static void input(Path file) {
        input(file, "the file " + file.toAbsolutePath().normalize());
    }

    /** {@link #input}, with what the file is in words ("the policy the run of --spec threw with"). */
    static synchronized void input(Path file, String what) {
        DECLARED_INPUTS.put(file.toAbsolutePath().normalize(), what);
    }

    /** Notes a folder the command created for its output (a run folder): removed again if the command fails and leaves it empty. */
    static synchronized void created(Path dir) {
        CREATED.add(dir.toAbsolutePath().normalize());
    }

    /** A file the command will write (ignored when null). */
    OutputPaths file(String option, Path file) {
        return add(option, file, false, false);
    }

    /** Files the command will write, all named by {@code option} (a .gltf and its .bin). */
    OutputPaths files(String option, List<Path> files) {
        files.forEach(f -> add(option, f, false, false));
        return this;
    }

    /** A file the command will write, held by this process alone while it runs (ignored when null). */
    OutputPaths heldFile(String option, Path file) {
        return add(option, file, false, true);
    }

    /** A folder the command writes into, with the names of what it writes there ({@code "frames/"} a folder). */
    OutputPaths folder(String option, Path dir, String... inside) {
        return add(option, dir, true, false, inside);
    }

    /** {@link #folder}, held by this process alone while it runs. */
    OutputPaths heldFolder(String option, Path dir, String... inside) {
        return add(option, dir, true, true, inside);
    }

    private OutputPaths add(String option, Path path, boolean isFolder, boolean held, String... inside) {
        if (path != null) {
            wanted.add(new Wanted(option, path.toAbsolutePath().normalize(), isFolder, held, List.of(inside)));
        }
        return this;
    }

    /** Checks every path, then creates the folders they need and holds the held ones. */
    void check() {
        synchronized (OutputPaths.class) {
            wanted.forEach(w -> OUTPUT_OPTIONS.add(w.option()));
            Map<Path, String> outputs = new LinkedHashMap<>(OUTPUTS);
            for (Wanted w : wanted) {
                checkOne(w, w.path(), w.isFolder(), outputs);
                for (String name : w.inside()) {
                    boolean folder = name.endsWith("/");
                    checkOne(w, w.path().resolve(folder ? name.substring(0, name.length() - 1) : name), folder, outputs);
                }
                probe(w);
            }
            OUTPUTS.putAll(outputs);
            for (Wanted w : wanted) {
                create(w, w.isFolder() ? w.path() : w.path().getParent());
            }
        }
        for (Wanted w : wanted) {
            if (w.held() && w.isFolder()) {
                Locks.holdFolder(w.path(), w.label(), note -> System.out.println("handsim: " + note));
            } else if (w.held()) {
                Locks.holdFile(w.path(), w.label(), note -> System.out.println("handsim: " + note));
            }
        }
    }

    /** The checks of one path {@code p} of {@code w} (itself, or a file it writes inside its folder). */
    private static void checkOne(Wanted w, Path p, boolean isFolder, Map<Path, String> outputs) {
        String what = p.equals(w.path()) ? w.label() : w.label() + " (its " + w.path().relativize(p) + ")";
        checkName(what, p);
        if (isFolder && Files.exists(p) && !Files.isDirectory(p)) {
            throw refused(what, "is a file, not a folder");
        }
        if (!isFolder && Files.isDirectory(p)) {
            throw refused(what, "is a folder: give a file name");
        }
        if (!isFolder && Files.exists(p) && !Files.isRegularFile(p)) {
            throw refused(what, "is not a plain file (a device or a pipe?): give a file name");
        }
        Path real = canonical(p);
        for (String tree : List.of("models", "configs")) {
            Path inputs = canonical(Home.resolve(tree));
            if (real.startsWith(inputs)) {
                throw refused(what, "is " + (real.equals(inputs) ? "" : "under ") + "the project's " + tree + "/, which holds "
                        + "handsim's inputs: write results elsewhere");
            }
        }
        String input = inputNaming(p, real);
        if (input != null) {
            throw refused(what, "is " + input + ", an input of this run: writing it would destroy it");
        }
        for (Map.Entry<Path, String> o : outputs.entrySet()) {
            if (o.getKey().equals(real) && !o.getValue().equals(what)) { // the same output declared again is the same output
                throw refused(what, "is also written as " + o.getValue() + ": give each output a path of its own");
            }
        }
        outputs.put(real, what);
    }

    /** The input that {@code p} (canonically {@code real}) is, in words, or null when it is none. */
    private static String inputNaming(Path p, Path real) {
        Map<Path, String> inputs = new LinkedHashMap<>();
        for (Map.Entry<Path, String> named : OPTION_PATHS) {
            if (!OUTPUT_OPTIONS.contains(named.getValue()) && !OUTPUT_OPTION_NAMES.contains(named.getValue())) {
                inputs.putIfAbsent(named.getKey(), "the file of " + named.getValue());
            }
        }
        inputs.putAll(DECLARED_INPUTS);
        for (Map.Entry<Path, String> in : inputs.entrySet()) {
            if (Files.isDirectory(in.getKey())) {
                continue; // an input folder: what the run reads inside it is declared with input()
            }
            if (canonical(in.getKey()).equals(real) || Files.exists(p) && Files.exists(in.getKey()) && sameFile(p, in.getKey())) {
                return in.getValue();
            }
        }
        return null;
    }

    /** Names the file system takes: each at most 255 bytes, a file's short enough for its temporary name, the whole path at most 4095. */
    private static void checkName(String what, Path p) {
        if (p.toString().getBytes(StandardCharsets.UTF_8).length > PATH_MAX) {
            throw refused(what, "is longer than the " + PATH_MAX + " bytes a path may have");
        }
        for (Path part : p) {
            int bytes = part.toString().getBytes(StandardCharsets.UTF_8).length;
            if (bytes > NAME_MAX) {
                throw refused(what, "has a name of " + bytes + " bytes, more than the " + NAME_MAX + " a file name may have");
            }
        }
        Path name = p.getFileName();
        int bytes = name == null ? 0 : name.toString().getBytes(StandardCharsets.UTF_8).length;
        if (bytes > NAME_MAX - TEMPORARY_NAME_EXTRA) {
            throw refused(what, "has a name of " + bytes + " bytes: it is written through a temporary file whose name adds "
                    + TEMPORARY_NAME_EXTRA + ", so at most " + (NAME_MAX - TEMPORARY_NAME_EXTRA));
        }
    }

    /**
     * Shows that files can be created where {@code w} goes: creates one and deletes it in the
     * nearest folder that exists, named as long as the temporary file of an atomic write of it.
     */
    private static void probe(Wanted w) {
        Path existing = w.isFolder() ? w.path() : w.path().getParent();
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null || !Files.isDirectory(existing)) {
            throw refused(w.label(), "cannot be made: " + existing + " is a file, not a folder");
        }
        String name = w.isFolder() ? "" : w.path().getFileName().toString();
        Path probe = existing.resolve("." + name + ".handsim-probe-" + ProcessHandle.current().pid() + "-" + System.nanoTime());
        try {
            Files.createFile(probe);
            Files.delete(probe);
        } catch (IOException | InvalidPathException e) {
            throw refused(w.label(), "cannot be written: no such new file can be made in " + existing + " ("
                    + (e instanceof IOException io ? reason(io) : e.getMessage()) + ")");
        }
    }

    /** Creates {@code dir} and the folders above it that are missing, noting which it made. */
    private static void create(Wanted w, Path dir) {
        List<Path> missing = new ArrayList<>();
        for (Path d = dir; d != null && !Files.exists(d); d = d.getParent()) {
            missing.add(0, d);
        }
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw refused(w.label(), "cannot create " + dir + " (" + reason(e) + ")");
        }
        CREATED.addAll(missing);
    }

    /** {@code p} as the file system resolves it: symbolic links of the part that exists followed, the rest normalised. */
    static Path canonical(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        Path existing = abs;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null) {
            return abs;
        }
        try {
            return existing.toRealPath().resolve(existing.relativize(abs)).normalize();
        } catch (IOException e) {
            return abs;
        }
    }

    private static boolean sameFile(Path a, Path b) {
        try {
            return Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }

    private static IllegalArgumentException refused(String what, String problem) {
        return new IllegalArgumentException(what + " " + problem);
    }

    /** Why a file operation failed, in a few words (Java's messages are often just the path). */
    static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such file or folder";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }
}
