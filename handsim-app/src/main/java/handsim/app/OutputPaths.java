package handsim.app;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The output paths a command was given, checked before any work starts: each file's folder is
 * created or shown to be writable (by creating and deleting a probe file in it), a file that
 * exists as a folder or as something other than a plain file is refused, and so is a folder
 * that exists as a file. The first problem fails with one line naming the option and the path
 * ({@link IllegalArgumentException}: exit status 2); nothing is created until every path passed.
 *
 * <pre>
 * new OutputPaths().file("--json", json).file("--csv", csv).folder("--out", dir).check();
 * </pre>
 */
final class OutputPaths {

    private record Wanted(String option, Path path, boolean isFolder) {
    }

    private final List<Wanted> wanted = new ArrayList<>();

    /** A file the command will write (ignored when null). */
    OutputPaths file(String option, Path file) {
        if (file != null) {
            wanted.add(new Wanted(option, file.toAbsolutePath().normalize(), false));
        }
        return this;
    }

    /** A folder the command will write into (ignored when null). */
    OutputPaths folder(String option, Path dir) {
        if (dir != null) {
            wanted.add(new Wanted(option, dir.toAbsolutePath().normalize(), true));
        }
        return this;
    }

    /** Checks every path, then creates the folders they need. */
    void check() {
        for (Wanted w : wanted) {
            Path p = w.path();
            if (w.isFolder() && Files.exists(p) && !Files.isDirectory(p)) {
                throw refused(w, "is a file, not a folder");
            }
            if (!w.isFolder() && Files.isDirectory(p)) {
                throw refused(w, "is a folder: give a file name");
            }
            if (!w.isFolder() && Files.exists(p) && !Files.isRegularFile(p)) {
                throw refused(w, "is not a plain file (a device or a pipe?): give a file name");
            }
            Path existing = w.isFolder() ? p : p.getParent();
            while (existing != null && !Files.exists(existing)) {
                existing = existing.getParent();
            }
            if (existing == null || !Files.isDirectory(existing)) {
                throw refused(w, "cannot be made: " + existing + " is a file, not a folder");
            }
            probe(w, existing, w.isFolder() ? "" : w.path().getFileName().toString());
        }
        for (Wanted w : wanted) {
            Path dir = w.isFolder() ? w.path() : w.path().getParent();
            try {
                Files.createDirectories(dir);
            } catch (IOException e) {
                throw refused(w, "cannot create " + dir + " (" + reason(e) + ")");
            }
        }
    }

    /**
     * Shows that files can be created in {@code dir}: creates one and deletes it, named as long
     * as the temporary file of an atomic write of {@code name} will be (a name too long fails here).
     */
    private static void probe(Wanted w, Path dir, String name) {
        Path probe = dir.resolve("." + name + ".handsim-probe-" + ProcessHandle.current().pid() + "-" + System.nanoTime());
        try {
            Files.createFile(probe);
            Files.delete(probe);
        } catch (IOException | java.nio.file.InvalidPathException e) {
            throw refused(w, "cannot be written: no such new file can be made in " + dir + " ("
                    + (e instanceof IOException io ? reason(io) : e.getMessage()) + ")");
        }
    }

    private static IllegalArgumentException refused(Wanted w, String problem) {
        return new IllegalArgumentException(w.option() + " " + w.path() + " " + problem);
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
