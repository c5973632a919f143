package handsim.spark;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;

/**
 * handsim's code as executors get it: the classpath the launcher names ({@code
 * -Dhandsim.classpath}: the modules and their libraries, Spark's own jars left out, since the
 * cluster has them), else this JVM's. For shipping, each class folder is packed into a jar.
 */
final class CodeJars {

    private CodeJars() {
    }

    /** The classpath executors read at the driver's paths. */
    static String classpath() {
        String named = System.getProperty("handsim.classpath");
        return named != null ? named : System.getProperty("java.class.path");
    }

    /** The jars to ship with the job: the classpath's jars, and its class folders packed into temporary jars. */
    static List<String> forExecutors() {
        List<String> jars = new ArrayList<>();
        try {
            Path packed = Files.createTempDirectory("handsim-jars");
            packed.toFile().deleteOnExit();
            int n = 0;
            for (String entry : classpath().split(File.pathSeparator)) {
                Path p = Path.of(entry);
                if (Files.isDirectory(p)) {
                    Path jar = packed.resolve("classes-" + (n++) + ".jar");
                    pack(p, jar);
                    jars.add(jar.toString());
                } else if (entry.endsWith(".jar") && Files.isRegularFile(p)) {
                    jars.add(p.toString());
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot pack handsim's classes into jars for the executors", e);
        }
        return jars;
    }

    private static void pack(Path dir, Path jar) throws IOException {
        try (OutputStream file = Files.newOutputStream(jar); JarOutputStream out = new JarOutputStream(file);
                Stream<Path> walk = Files.walk(dir)) {
            for (Path f : (Iterable<Path>) walk.filter(Files::isRegularFile).sorted()::iterator) {
                out.putNextEntry(new JarEntry(dir.relativize(f).toString().replace(File.separatorChar, '/')));
                Files.copy(f, out);
                out.closeEntry();
            }
        }
        jar.toFile().deleteOnExit();
    }
}
