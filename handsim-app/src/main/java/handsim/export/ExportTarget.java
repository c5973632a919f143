package handsim.export;

import handsim.report.Outputs;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * Where and how a run's animation is written, checked before anything is simulated: the format
 * (glTF or BVH, named or read from the file's extension), the file's extension, and that its
 * folder can be written. {@link #write} writes through {@link Outputs} (a temporary file beside
 * the target moved into place), so a failed or interrupted export leaves no partial file.
 */
public final class ExportTarget {

    /** The two formats and the extensions each is written with. */
    public enum Format {
        GLTF(".glb", ".gltf"),
        BVH(".bvh");

        final List<String> extensions;

        Format(String... extensions) {
            this.extensions = List.of(extensions);
        }

        public String lower() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    private final Path file;
    private final Format format;

    private ExportTarget(Path file, Format format) {
        this.file = file;
        this.format = format;
    }

    /**
     * The target {@code file} in {@code format} ("gltf", "bvh", or null to go by the extension);
     * {@code fileOption} and {@code formatOption} name the command-line options in the one-line
     * message of the {@link IllegalArgumentException} thrown for a request that cannot be met.
     */
    public static ExportTarget of(Path file, String format, String fileOption, String formatOption) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        String lowerName = name.toLowerCase(Locale.ROOT);
        Format f = null;
        if (format != null) {
            for (Format candidate : Format.values()) {
                f = candidate.lower().equals(format.toLowerCase(Locale.ROOT)) ? candidate : f;
            }
            if (f == null) {
                throw new IllegalArgumentException(formatOption + " must be gltf or bvh, got \"" + format + "\"");
            }
        } else {
            for (Format candidate : Format.values()) {
                f = candidate.extensions.stream().anyMatch(lowerName::endsWith) ? candidate : f;
            }
            if (f == null) {
                throw new IllegalArgumentException(fileOption + " must end in .glb, .gltf or .bvh, got " + file);
            }
        }
        Format chosen = f;
        if (chosen.extensions.stream().noneMatch(e -> lowerName.endsWith(e) && lowerName.length() > e.length())) {
            throw new IllegalArgumentException(fileOption + " must be a file ending in " + String.join(" or ", chosen.extensions)
                    + " for " + chosen.lower() + ", got " + file);
        }
        Path abs = file.toAbsolutePath();
        if (Files.isDirectory(abs)) {
            throw new IllegalArgumentException(fileOption + " is a folder, not a file: " + file);
        }
        Path dir = abs.getParent();
        try {
            Files.createDirectories(dir);
            Files.delete(Files.createTempFile(dir, "." + name + ".", ".tmp"));
        } catch (IOException | SecurityException e) {
            throw new IllegalArgumentException(fileOption + ": cannot write into " + dir + " (" + reason(e) + ")");
        }
        return new ExportTarget(abs, chosen);
    }

    public Path file() {
        return file;
    }

    /** A file to write and its whole content. */
    public record FileContent(Path file, byte[] bytes) {
    }

    /** The files a glTF document makes at this target, in the order to write them: a .gltf's .bin first, so the .gltf never lacks it. */
    List<FileContent> gltfFiles(GltfDocument.Gltf gltf) {
        if (isSeparateGltf()) {
            return List.of(new FileContent(binFile(), gltf.bin()), new FileContent(file, gltf.gltf(binFile().getFileName().toString())));
        }
        return List.of(new FileContent(file, gltf.glb()));
    }

    public Format format() {
        return format;
    }

    /** The files written: the target, and for a .gltf its .bin beside it. */
    public List<Path> files() {
        return isSeparateGltf() ? List.of(file, binFile()) : List.of(file);
    }

    /** Writes {@code clip} (with {@code options}' extras for glTF), each file moved into place whole. */
    public void write(MotionClip clip, ExportOptions options) throws IOException {
        if (format == Format.BVH) {
            writeAtomically(List.of(file), List.of(BvhWriter.write(clip).getBytes(StandardCharsets.US_ASCII)));
            return;
        }
        List<FileContent> files = gltfFiles(GltfWriter.build(clip, options));
        writeAtomically(files.stream().map(FileContent::file).toList(), files.stream().map(FileContent::bytes).toList());
    }

    private boolean isSeparateGltf() {
        return format == Format.GLTF && file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gltf");
    }

    private Path binFile() {
        String name = file.getFileName().toString();
        return file.resolveSibling(name.substring(0, name.length() - ".gltf".length()) + ".bin");
    }

    /** Writes every file atomically ({@link Outputs}), in order: a .gltf is never in place without its .bin. */
    private static void writeAtomically(List<Path> targets, List<byte[]> contents) throws IOException {
        for (int i = 0; i < targets.size(); i++) {
            byte[] bytes = contents.get(i);
            Outputs.write(targets.get(i), out -> out.write(bytes));
        }
    }

    private static String reason(Exception e) {
        String m = e.getMessage();
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof java.nio.file.FileSystemException fs && fs.getReason() != null) {
            return fs.getReason();
        }
        return m == null ? e.getClass().getSimpleName() : m;
    }
}
