package handsim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Every package boundary of handsim, read from the sources' import lines: which handsim packages
 * each package may import (dependencies point one way, from {@code math} up to {@code app}),
 * which libraries live in one package only (ode4j in {@code sim.ode}, LWJGL in {@code viewer},
 * DL4J in {@code learn}, picocli in {@code app}, the sparse solvers in {@code cards.linalg}), and
 * every package's {@code package-info.java}, which names the packages it may import.
 */
@Tag("fast")
class PackageRulesTest {

    private static final Path MAIN = Path.of("src/main/java");

    /**
     * The handsim packages each package may import (besides itself). A package not listed here
     * fails the test: a new package says where it stands. {@code handsim.cards.*} covers the card
     * system's subpackages, which may also import each other.
     */
    static final Map<String, Set<String>> MAY_IMPORT = Map.ofEntries(
            Map.entry("handsim.math", Set.of()),
            Map.entry("handsim.config", Set.of("math")),
            Map.entry("handsim.model", Set.of("math", "config")),
            Map.entry("handsim.kin", Set.of("math", "model")),
            Map.entry("handsim.sim", Set.of("math", "config", "model", "kin")),
            Map.entry("handsim.sim.ode", Set.of("math", "model", "kin", "sim")),
            Map.entry("handsim.mesh", Set.of("math", "model")),
            Map.entry("handsim.report", Set.of("config")),
            Map.entry("handsim.rollout", Set.of()),
            Map.entry("handsim.control", Set.of("math", "config", "model", "kin", "sim")),
            Map.entry("handsim.task", Set.of("math", "config", "model", "kin", "sim", "control")),
            Map.entry("handsim.evaluation", Set.of("math", "config", "model", "kin", "sim", "control", "task", "rollout", "report")),
            Map.entry("handsim.scene", Set.of("math", "config", "model", "kin", "sim", "control", "task", "evaluation")),
            Map.entry("handsim.learn", Set.of("config", "report", "rollout")),
            Map.entry("handsim.train", Set.of("math", "config", "sim", "control", "task", "evaluation", "rollout", "learn", "report")),
            Map.entry("handsim.export", Set.of("math", "model", "kin", "mesh", "sim", "task")),
            Map.entry("handsim.viewer", Set.of("math", "config", "model", "kin", "mesh", "sim", "task", "scene", "export", "report")),
            Map.entry("handsim.cards.*", Set.of("config", "report")),
            Map.entry("handsim.app", Set.of("*")));

    /** Libraries that one package alone may import (prefixes of the import names). */
    static final Map<String, String> ONLY_IN = Map.of(
            "org.ode4j", "handsim.sim.ode",
            "org.lwjgl", "handsim.viewer",
            "org.deeplearning4j", "handsim.learn",
            "org.nd4j", "handsim.learn",
            "picocli", "handsim.app",
            "org.ojalgo", "handsim.cards.linalg",
            "edu.emory.mathcs.csparsej", "handsim.cards.linalg");

    private static final Pattern IMPORT = Pattern.compile("^import (?:static )?([a-z][\\w]*(?:\\.[a-z][\\w]*)*)\\.[A-Z*]", Pattern.MULTILINE);

    /** Each main source file's package and the packages it imports. */
    private static Map<Path, List<String>> imports() throws IOException {
        Map<Path, List<String>> out = new TreeMap<>();
        try (Stream<Path> files = Files.walk(MAIN.resolve("handsim"))) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                Matcher m = IMPORT.matcher(read(f));
                List<String> found = new ArrayList<>();
                while (m.find()) {
                    found.add(m.group(1));
                }
                out.put(f, found);
            }
        }
        return out;
    }

    private static String packageOf(Path file) {
        return MAIN.relativize(file.getParent()).toString().replace('/', '.');
    }

    /** The rule that holds for {@code pkg}: its own entry, or the card system's. */
    private static String ruleOf(String pkg) {
        return pkg.startsWith("handsim.cards") ? "handsim.cards.*" : pkg;
    }

    @Test
    void everyPackageImportsOnlyTheHandsimPackagesItsRuleAllows() throws IOException {
        List<String> broken = new ArrayList<>();
        for (var e : imports().entrySet()) {
            String pkg = packageOf(e.getKey());
            Set<String> allowed = MAY_IMPORT.get(ruleOf(pkg));
            if (allowed == null) {
                broken.add(pkg + " has no rule in PackageRulesTest.MAY_IMPORT");
                continue;
            }
            for (String imported : e.getValue()) {
                if (!imported.startsWith("handsim.") || imported.equals(pkg) || allowed.contains("*")
                        || pkg.startsWith("handsim.cards") && imported.startsWith("handsim.cards")) {
                    continue;
                }
                if (!allowed.contains(imported.substring("handsim.".length()))) {
                    broken.add(e.getKey() + " imports " + imported);
                }
            }
        }
        assertEquals(List.of(), broken);
    }

    @Test
    void ode4jLwjglDl4jPicocliAndTheSparseSolversEachLiveInOnePackage() throws IOException {
        List<String> broken = new ArrayList<>();
        for (var e : imports().entrySet()) {
            String pkg = packageOf(e.getKey());
            for (String imported : e.getValue()) {
                ONLY_IN.forEach((library, home) -> {
                    if (imported.startsWith(library) && !pkg.equals(home)) {
                        broken.add(e.getKey() + " imports " + imported + " (only " + home + " may)");
                    }
                });
            }
        }
        assertEquals(List.of(), broken);
    }

    @Test
    void nothingBelowTheAppImportsIt() throws IOException {
        List<String> broken = new ArrayList<>();
        for (var e : imports().entrySet()) {
            if (!packageOf(e.getKey()).equals("handsim.app") && e.getValue().stream().anyMatch(i -> i.startsWith("handsim.app"))) {
                broken.add(e.getKey().toString());
            }
        }
        assertEquals(List.of(), broken);
    }

    /** Every package says what lives there and names each handsim package it may import. */
    @Test
    void everyPackageInfoNamesThePackagesItsPackageMayImport() throws IOException {
        Set<String> packages = new TreeSet<>();
        imports().keySet().forEach(f -> packages.add(packageOf(f)));
        List<String> broken = new ArrayList<>();
        for (String pkg : packages) {
            Path info = MAIN.resolve(pkg.replace('.', '/')).resolve("package-info.java");
            if (!Files.exists(info)) {
                broken.add(pkg + " has no package-info.java");
                continue;
            }
            String text = read(info);
            Set<String> allowed = MAY_IMPORT.getOrDefault(ruleOf(pkg), Set.of());
            for (String other : allowed) {
                if (!other.equals("*") && !text.contains("handsim." + other)) {
                    broken.add(info + " does not name handsim." + other + ", which its package may import");
                }
            }
        }
        assertEquals(List.of(), broken);
    }

    private static String read(Path f) {
        try {
            return Files.readString(f);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
