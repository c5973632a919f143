package handsim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
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
 * handsim's architecture, read from the sources' import lines and the modules' pom.xml files.
 * Modules: which handsim modules each may depend on, which packages each holds, which libraries
 * each declares. Packages: which handsim packages each may import (dependencies point one way,
 * from {@code math} up to {@code app}), which libraries live in one package only (ode4j in
 * {@code sim.ode}, LWJGL in {@code viewer}, DL4J in {@code learn}, picocli in {@code app}, the
 * sparse solvers in {@code cards.linalg}), and every package's {@code package-info.java}, which
 * names the packages it may import. Runs from the project root (the surefire working directory).
 */
@Tag("fast")
class ArchitectureRulesTest {

    /** A Maven module: the modules it may depend on, its packages, the libraries its pom declares. */
    record Module(Set<String> mayDependOn, Set<String> packages, Set<String> libraries) {
    }

    /**
     * The modules bottom up. A package belongs to exactly one module; {@code handsim.cards.*}
     * covers the card system's subpackages. A library's artifactId may appear in the dependencies
     * of the modules that list it only.
     */
    static final Map<String, Module> MODULES = orderedMap(
            "handsim-common", new Module(Set.of(),
                    Set.of("handsim.math", "handsim.config", "handsim.report", "handsim.rollout"),
                    Set.of("jackson-databind")),
            "handsim-hand", new Module(Set.of("handsim-common"),
                    Set.of("handsim.model", "handsim.kin", "handsim.mesh", "handsim.sim", "handsim.sim.island", "handsim.sim.ode", "handsim.control",
                            "handsim.task", "handsim.planning", "handsim.evaluation", "handsim.taskdef", "handsim.spec", "handsim.learn",
                            "handsim.train"),
                    Set.of("jackson-databind", "core", "deeplearning4j-nn", "nd4j-native", "commons-math3")),
            "handsim-cards", new Module(Set.of("handsim-common"),
                    Set.of("handsim.cards.*"),
                    Set.of("jackson-databind", "ojalgo", "csparsej", "commons-math3")),
            "handsim-app", new Module(Set.of("handsim-common", "handsim-hand", "handsim-cards"),
                    Set.of("handsim.app", "handsim.viewer", "handsim.scene", "handsim.export"),
                    Set.of("jackson-databind", "picocli", "lwjgl", "lwjgl-glfw", "lwjgl-opengl", "slf4j-simple")),
            // Spark provided (off every other classpath); handsim-app for its tests only, which run the commands on a cluster
            // (slf4j-simple: excluded from them, Spark bringing its own logging)
            "handsim-spark", new Module(Set.of("handsim-common", "handsim-app"),
                    Set.of("handsim.spark"),
                    Set.of("spark-core_2.13", "jackson-databind", "slf4j-simple")));

    /**
     * The handsim packages each package may import (besides itself). A package not listed here
     * fails the test: a new package says where it stands. {@code handsim.cards.*} covers the card
     * system's subpackages, which may also import each other, but for those with an entry of their own.
     */
    static final Map<String, Set<String>> MAY_IMPORT = Map.ofEntries(
            Map.entry("handsim.math", Set.of()),
            Map.entry("handsim.config", Set.of("math")),
            Map.entry("handsim.model", Set.of("math", "config")),
            Map.entry("handsim.kin", Set.of("math", "model")),
            Map.entry("handsim.sim", Set.of("math", "config", "model", "kin")),
            Map.entry("handsim.sim.island", Set.of("math")),
            Map.entry("handsim.sim.ode", Set.of("math", "model", "kin", "sim", "sim.island")),
            Map.entry("handsim.mesh", Set.of("math", "model")),
            Map.entry("handsim.report", Set.of("config")),
            Map.entry("handsim.rollout", Set.of("config", "report")),
            Map.entry("handsim.control", Set.of("math", "config", "model", "kin", "sim")),
            Map.entry("handsim.task", Set.of("math", "config", "model", "kin", "sim", "control")),
            Map.entry("handsim.planning", Set.of("math", "config", "sim", "control", "task")),
            Map.entry("handsim.evaluation", Set.of("math", "config", "model", "kin", "sim", "control", "task", "planning", "rollout", "report")),
            Map.entry("handsim.taskdef", Set.of("math", "config", "task", "evaluation")),
            Map.entry("handsim.spec", Set.of("config", "model", "kin", "sim", "control", "task", "taskdef", "planning", "evaluation")),
            Map.entry("handsim.scene", Set.of("math", "config", "model", "kin", "sim", "control", "task", "planning", "evaluation", "taskdef")),
            Map.entry("handsim.learn", Set.of("config", "report", "rollout")),
            Map.entry("handsim.train", Set.of("math", "config", "sim", "control", "task", "planning", "evaluation", "taskdef", "rollout", "learn",
                    "report")),
            Map.entry("handsim.export", Set.of("math", "model", "kin", "mesh", "sim", "task", "report")),
            Map.entry("handsim.viewer", Set.of("math", "config", "model", "kin", "mesh", "sim", "task", "scene", "export", "report")),
            Map.entry("handsim.cards.*", Set.of("config", "report")),
            // the study's trials also run on a cluster's executors (handsim.rollout's calls)
            Map.entry("handsim.cards.study", Set.of("config", "report", "rollout")),
            Map.entry("handsim.spark", Set.of("config", "report", "rollout")),
            Map.entry("handsim.app", Set.of("*")));

    /** Libraries that one package alone may import (prefixes of the import names). */
    static final Map<String, String> ONLY_IN = Map.of(
            "org.ode4j", "handsim.sim.ode",
            "org.lwjgl", "handsim.viewer",
            "org.deeplearning4j", "handsim.learn",
            "org.nd4j", "handsim.learn",
            "picocli", "handsim.app",
            "org.ojalgo", "handsim.cards.linalg",
            "edu.emory.mathcs.csparsej", "handsim.cards.linalg",
            "org.apache.spark", "handsim.spark",
            "scala", "handsim.spark");

    private static final Pattern IMPORT = Pattern.compile("^import (?:static )?([a-z][\\w]*(?:\\.[a-z][\\w]*)*)\\.[A-Z*]", Pattern.MULTILINE);
    private static final Pattern DEPENDENCIES = Pattern.compile("<dependencies>(.*?)</dependencies>", Pattern.DOTALL);
    private static final Pattern ARTIFACT = Pattern.compile("<artifactId>([\\w.-]+)</artifactId>");

    /** A main source file: its module, its package, the packages it imports. */
    record Source(Path file, String module, String pkg, List<String> imports) {
    }

    /** Every main source file of every module directory ({@code handsim-*}). */
    private static List<Source> sources() throws IOException {
        List<Source> out = new ArrayList<>();
        for (String module : moduleDirectories()) {
            Path main = Path.of(module, "src/main/java");
            if (!Files.isDirectory(main)) {
                continue;
            }
            try (Stream<Path> files = Files.walk(main)) {
                for (Path f : files.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                    Matcher m = IMPORT.matcher(read(f));
                    List<String> found = new ArrayList<>();
                    while (m.find()) {
                        found.add(m.group(1));
                    }
                    out.add(new Source(f, module, main.relativize(f.getParent()).toString().replace('/', '.'), found));
                }
            }
        }
        return out;
    }

    private static Set<String> moduleDirectories() throws IOException {
        try (Stream<Path> dirs = Files.list(Path.of("."))) {
            Set<String> out = new TreeSet<>();
            dirs.filter(d -> Files.exists(d.resolve("pom.xml"))).forEach(d -> out.add(d.getFileName().toString()));
            return out;
        }
    }

    /** The rule that holds for {@code pkg}: its own entry, or the card system's. */
    private static String ruleOf(String pkg) {
        return pkg.startsWith("handsim.cards") ? "handsim.cards.*" : pkg;
    }

    /** The import rule of {@code pkg}: its own entry in MAY_IMPORT when it has one, else the one that covers it. */
    private static String importRuleOf(String pkg) {
        return MAY_IMPORT.containsKey(pkg) ? pkg : ruleOf(pkg);
    }

    /** The module that holds {@code pkg}, or null when none does. */
    private static String moduleOf(String pkg) {
        for (var e : MODULES.entrySet()) {
            if (e.getValue().packages().contains(ruleOf(pkg))) {
                return e.getKey();
            }
        }
        return null;
    }

    @Test
    void theModulesAreTheOnesListedAndTheParentBuildsThemAll() throws IOException {
        assertEquals(new TreeSet<>(MODULES.keySet()), moduleDirectories(), "module directories with a pom.xml");
        String parent = read(Path.of("pom.xml"));
        List<String> missing = new ArrayList<>();
        for (String m : MODULES.keySet()) {
            if (!parent.contains("<module>" + m + "</module>")) {
                missing.add(m);
            }
        }
        assertEquals(List.of(), missing, "modules the parent pom.xml does not build");
    }

    @Test
    void everyPackageLivesInItsModule() throws IOException {
        List<String> broken = new ArrayList<>();
        for (Source s : sources()) {
            String home = moduleOf(s.pkg());
            if (!s.module().equals(home)) {
                broken.add(s.file() + ": " + s.pkg() + " belongs to " + (home == null ? "no module in ArchitectureRulesTest.MODULES" : home));
            }
        }
        assertEquals(List.of(), broken);
    }

    /** A module's pom depends on the handsim modules below it that it may use, and declares only its own libraries. */
    @Test
    void everyModuleDependsOnlyOnTheModulesAndLibrariesItsRuleAllows() {
        List<String> broken = new ArrayList<>();
        Set<String> everyLibrary = new TreeSet<>();
        MODULES.values().forEach(m -> everyLibrary.addAll(m.libraries()));
        MODULES.forEach((name, module) -> {
            Matcher deps = DEPENDENCIES.matcher(read(Path.of(name, "pom.xml")));
            while (deps.find()) {
                Matcher a = ARTIFACT.matcher(deps.group(1));
                while (a.find()) {
                    String artifact = a.group(1);
                    boolean handsim = artifact.startsWith("handsim-");
                    if (handsim && !module.mayDependOn().contains(artifact)) {
                        broken.add(name + " depends on " + artifact);
                    } else if (!handsim && everyLibrary.contains(artifact) && !module.libraries().contains(artifact)) {
                        broken.add(name + " declares " + artifact + ", a library of another module");
                    }
                }
            }
        });
        assertEquals(List.of(), broken);
    }

    @Test
    void everyPackageImportsOnlyTheHandsimPackagesItsRuleAllows() throws IOException {
        List<String> broken = new ArrayList<>();
        for (Source s : sources()) {
            Set<String> allowed = MAY_IMPORT.get(importRuleOf(s.pkg()));
            if (allowed == null) {
                broken.add(s.pkg() + " has no rule in ArchitectureRulesTest.MAY_IMPORT");
                continue;
            }
            for (String imported : s.imports()) {
                if (!imported.startsWith("handsim.") || imported.equals(s.pkg()) || allowed.contains("*")
                        || s.pkg().startsWith("handsim.cards") && imported.startsWith("handsim.cards")) {
                    continue;
                }
                if (!allowed.contains(imported.substring("handsim.".length()))) {
                    broken.add(s.file() + " imports " + imported);
                }
            }
        }
        assertEquals(List.of(), broken);
    }

    /** What a package may import lives in its own module or one its module may depend on. */
    @Test
    void everyImportAllowedByAPackageRuleCrossesOnlyAllowedModules() {
        List<String> broken = new ArrayList<>();
        MAY_IMPORT.forEach((pkg, allowed) -> {
            String from = moduleOf(pkg);
            for (String other : allowed) {
                String to = other.equals("*") ? null : moduleOf("handsim." + other);
                if (to != null && !to.equals(from) && !MODULES.get(from).mayDependOn().contains(to)) {
                    broken.add(pkg + " (" + from + ") may import handsim." + other + " (" + to + ")");
                }
            }
        });
        assertEquals(List.of(), broken);
    }

    @Test
    void ode4jLwjglDl4jPicocliAndTheSparseSolversEachLiveInOnePackage() throws IOException {
        List<String> broken = new ArrayList<>();
        for (Source s : sources()) {
            for (String imported : s.imports()) {
                ONLY_IN.forEach((library, home) -> {
                    if (imported.startsWith(library) && !s.pkg().equals(home)) {
                        broken.add(s.file() + " imports " + imported + " (only " + home + " may)");
                    }
                });
            }
        }
        assertEquals(List.of(), broken);
    }

    @Test
    void nothingBelowTheAppImportsIt() throws IOException {
        List<String> broken = new ArrayList<>();
        for (Source s : sources()) {
            if (!s.pkg().equals("handsim.app") && s.imports().stream().anyMatch(i -> i.startsWith("handsim.app"))) {
                broken.add(s.file().toString());
            }
        }
        assertEquals(List.of(), broken);
    }

    /** Every package says what lives there and names each handsim package it may import. */
    @Test
    void everyPackageInfoNamesThePackagesItsPackageMayImport() throws IOException {
        Map<String, Path> packages = new TreeMap<>();
        for (Source s : sources()) {
            packages.putIfAbsent(s.pkg(), Path.of(s.module(), "src/main/java", s.pkg().replace('.', '/'), "package-info.java"));
        }
        List<String> broken = new ArrayList<>();
        packages.forEach((pkg, info) -> {
            if (!Files.exists(info)) {
                broken.add(pkg + " has no package-info.java");
                return;
            }
            String text = read(info);
            for (String other : MAY_IMPORT.getOrDefault(importRuleOf(pkg), Set.of())) {
                if (!other.equals("*") && !text.contains("handsim." + other)) {
                    broken.add(info + " does not name handsim." + other + ", which its package may import");
                }
            }
        });
        assertEquals(List.of(), broken);
    }

    private static Map<String, Module> orderedMap(Object... keysAndValues) {
        Map<String, Module> out = new LinkedHashMap<>();
        for (int i = 0; i < keysAndValues.length; i += 2) {
            out.put((String) keysAndValues[i], (Module) keysAndValues[i + 1]);
        }
        return out;
    }

    private static String read(Path f) {
        try {
            return Files.readString(f);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
