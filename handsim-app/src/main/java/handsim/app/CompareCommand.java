package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.taskdef.TaskDefinitions;
import handsim.evaluation.PairedLoops;
import handsim.report.Outputs;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code handsim compare}: two flip evaluations ({@code evaluate --task flip --json}) of the same
 * object and loop cap, compared seed by seed ({@link PairedLoops}).
 */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = "Compare two flip evaluations (the JSON files of evaluate --task flip --json) seed by seed: the mean "
                + "loops in a row of each on the seeds both ran, the mean of B - A with its paired standard error, and the "
                + "seeds whose loops differ.")
final class CompareCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "A", description = "the reference evaluation's JSON")
    Path a;

    @Parameters(index = "1", paramLabel = "B", description = "the evaluation compared with it")
    Path b;

    @Option(names = "--json", paramLabel = "FILE", description = "also write the comparison as JSON")
    Path json;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        new OutputPaths().file("--json", json).check();
        Json ja = flipEvaluation(a), jb = flipEvaluation(b);
        for (String field : List.of("object", "max_loops")) {
            if (!ja.get(field).node().equals(jb.get(field).node())) {
                throw new IllegalArgumentException("A and B differ in " + field + ": " + ja.get(field).node() + " in " + a + ", "
                        + jb.get(field).node() + " in " + b);
            }
        }
        PairedLoops p;
        try {
            p = PairedLoops.of(loopsBySeed(ja, a), loopsBySeed(jb, b));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(a + " and " + b + ": " + e.getMessage(), e);
        }
        int same = p.seeds().size() - p.changes().size();
        System.out.printf(Locale.ROOT, "flip task, %s, %d episodes on the same seeds (%s): A %.2f, B %.2f loops in a row; "
                + "B - A %+.2f (paired standard error %s)%n", ja.string("object"), p.seeds().size(), seedRanges(p.seeds()), p.meanA(),
                p.meanB(), p.meanDifference(), Double.isNaN(p.standardError()) ? "n/a: one seed"
                        : String.format(Locale.ROOT, "%.2f", p.standardError()));
        System.out.printf(Locale.ROOT, "seeds where B made more loops: %d, fewer: %d, as many: %d%s%n", p.better(), p.worse(), same,
                p.changes().isEmpty() ? "" : "; " + p.changes().stream()
                        .map(c -> "seed " + c.seed() + " " + c.loopsA() + " -> " + c.loopsB()).collect(Collectors.joining(", ")));
        if (!p.onlyA().isEmpty() || !p.onlyB().isEmpty()) {
            System.out.printf(Locale.ROOT, "left out: seeds only A ran: %d, only B ran: %d%n", p.onlyA().size(), p.onlyB().size());
        }
        if (json != null) {
            Outputs.writeJson(json, toJson(p, ja));
            System.out.println("wrote " + json);
        }
        return 0;
    }

    /** The comparison in the snake_case of evaluate's JSON, with where it came from. */
    private ObjectNode toJson(PairedLoops p, Json ja) {
        ObjectNode out = Json.mapper().createObjectNode();
        out.put("task", ja.string("task")).put("object", ja.string("object")).set("max_loops", ja.get("max_loops").node());
        out.put("a", a.toString()).put("b", b.toString());
        p.seeds().forEach(out.putArray("seeds")::add);
        out.put("mean_a", p.meanA()).put("mean_b", p.meanB()).put("mean_difference", p.meanDifference())
                .put("standard_error", p.standardError()).put("better", p.better()).put("worse", p.worse());
        var changes = out.putArray("changes");
        p.changes().forEach(c -> changes.addObject().put("seed", c.seed()).put("loops_a", c.loopsA()).put("loops_b", c.loopsB()));
        p.onlyA().forEach(out.putArray("only_a")::add);
        p.onlyB().forEach(out.putArray("only_b")::add);
        out.set("provenance", Provenance.of(spec.commandLine().getParseResult().originalArgs()));
        return out;
    }

    /** The JSON of a flip evaluation; anything else is refused, naming the file. */
    private static Json flipEvaluation(Path file) {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("no file " + file);
        }
        Json j = Json.load(file);
        if (j.has("copies")) {
            throw new IllegalArgumentException(file + " is a sensitivity run (evaluate --copies): compare reads flip evaluations "
                    + "without --copies");
        }
        if (!j.has("task") || !j.has("episodes") || !j.has("object")) {
            throw new IllegalArgumentException(file + " is not the JSON of an evaluation (evaluate --json)");
        }
        if (!j.has("max_loops") || !Wiring.shipped().task(TaskDefinitions.checkName(j.string("task"))).countsLoopsInARow()) {
            throw new IllegalArgumentException(file + " is an evaluation of the " + j.string("task") + " task: compare reads flip "
                    + "evaluations (loops in a row)");
        }
        return j;
    }

    /** Each episode's loops in a row by its seed; a seed twice is refused. */
    private static Map<Long, Integer> loopsBySeed(Json evaluation, Path file) {
        Map<Long, Integer> loops = new LinkedHashMap<>();
        for (Json e : evaluation.array("episodes")) {
            if (loops.put(e.longValue("seed"), e.integer("loops_completed")) != null) {
                throw new IllegalArgumentException(file + ": seed " + e.longValue("seed") + " appears twice");
            }
        }
        return loops;
    }

    /** Ascending seeds as ranges: 1-40, 101-180. */
    static String seedRanges(List<Long> seeds) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < seeds.size(); i++) {
            int j = i;
            while (j + 1 < seeds.size() && seeds.get(j + 1) == seeds.get(j) + 1) {
                j++;
            }
            s.append(s.length() == 0 ? "" : ", ").append(seeds.get(i)).append(j > i ? "-" + seeds.get(j) : "");
            i = j;
        }
        return s.toString();
    }
}
