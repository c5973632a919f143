package handsim.app;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sleight.CardSleight;
import handsim.cards.sleight.Sleights;
import handsim.cards.study.Study;
import handsim.cards.study.StudyConfig;
import handsim.cards.study.TrialRecord;
import handsim.cards.tpe.Param;
import handsim.config.Json;
import handsim.report.Outputs;
import handsim.rollout.LocalRollouts;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code handsim cards robust}: does a study's chosen trial still work when the fingers are a
 * little off? It replays the trial with each parameter moved by ±1 % of its search range, one
 * at a time, and with the chosen parameters on the other fingertip resolution, and counts the
 * replays that still meet every tolerance of the study config.
 */
@Command(name = "robust", mixinStandardHelpOptions = true,
        description = "Replay a study's chosen trial with each parameter moved by +-1 %% of its range, one at a time, and on the other "
                + "fingertip resolution (thesis <-> reduced, coarse -> reduced); report how many replays still meet the study's tolerances and write "
                + "robust.json into the study folder.")
final class CardsRobust implements Callable<Integer> {

    /** How far each parameter moves: a fraction of its search range. */
    static final double NUDGE = 0.01;

    static final String ROBUST_FILE = "robust.json";

    @Option(names = "--study", required = true, paramLabel = "DIR", description = "a study folder of cards optimize")
    Path studyDir;

    @Option(names = "--workers", paramLabel = "N", defaultValue = "2", description = "replays run on N threads (default: ${DEFAULT-VALUE})")
    int workers;

    /** One replay: what was changed, the parameters, and on which mesh. */
    record Replay(String label, Map<String, Double> params, boolean otherMesh) {
    }

    @Override
    public Integer call() throws IOException {
        if (workers < 1) {
            throw new IllegalArgumentException("--workers must be >= 1, got " + workers);
        }
        if (!Files.isRegularFile(studyDir.resolve(Study.STUDY_FILE))) {
            throw new IllegalArgumentException("--study " + studyDir + " holds no " + Study.STUDY_FILE + " (is it a study folder of cards optimize?)");
        }
        // robust.json is the one file it writes; the study folder is held, so no study or other replay writes it meanwhile
        new OutputPaths().heldFolder("--study", studyDir, ROBUST_FILE).check();
        Study study = Study.open(studyDir);
        StudyConfig config = study.config();
        if (!config.hasTolerances()) {
            throw new IllegalArgumentException("--study " + studyDir + ": its config gives no tolerance to meet for every objective");
        }
        TrialRecord chosen = study.chosen().orElseThrow(() -> new IllegalArgumentException("--study " + studyDir + " has no complete trial"));
        var inputs = Json.load(studyDir.resolve(Study.STUDY_FILE)).get("objective").node();
        String mesh = inputs.get("mesh").asText();
        String other = otherMesh(mesh);
        CardSleight same = Sleights.fromInputs(inputs, null, CardsCommand.checkpoints());
        CardSleight otherMesh = Sleights.fromInputs(inputs, other, CardsCommand.checkpoints());
        List<Replay> replays = replays(config, chosen);
        System.out.printf(Locale.ROOT, "handsim cards robust: %s, chosen trial %d (%s), %d replays (+-%.0f %% of each range, and on %s fingertips) "
                + "on %d threads%n", same.title(), chosen.number(), CardsOptimize.values(config, chosen), replays.size(), 100 * NUDGE, other, workers);
        same.startState(chosen.trialParams(config).values());
        List<ObjectNode> results;
        try (LocalRollouts<Void> pool = new LocalRollouts<>(workers, () -> null)) {
            results = pool.run(replays.size(), worker -> index -> replay(replays.get(index), same, otherMesh, config),
                    (index, r) -> System.out.println("  " + r.get("label").asText() + ": " + r.get("summary").asText()));
        }
        long met = results.stream().filter(r -> r.get("meetsTolerances").asBoolean()).count();
        ObjectNode report = Json.mapper().createObjectNode();
        report.put("trial", chosen.number());
        report.put("sleight", same.name());
        report.put("mesh", mesh);
        report.put("otherMesh", other);
        report.put("nudge", NUDGE);
        ArrayNode tol = report.putArray("tolerances");
        config.tolerances().forEach(tol::add);
        report.put("replays", results.size());
        report.put("meetTolerances", met);
        report.put("fraction", (double) met / results.size());
        ArrayNode list = report.putArray("results");
        results.forEach(list::add);
        Outputs.writeJson(studyDir.resolve(ROBUST_FILE), report);
        System.out.printf(Locale.ROOT, "%d of %d replays (%.0f %%) meet every tolerance; wrote %s%n", met, results.size(), 100.0 * met / results.size(),
                studyDir.resolve("robust.json"));
        return 0;
    }

    /** The other resolution of a study's fingertips: thesis and reduced each other's; coarse, a test mesh, against reduced. */
    static String otherMesh(String mesh) {
        return mesh.equals("reduced") ? "thesis" : "reduced";
    }

    /** Each parameter −1 % and +1 % of its range, one at a time, then the chosen parameters on the other mesh. */
    static List<Replay> replays(StudyConfig config, TrialRecord chosen) {
        Map<String, Double> base = chosen.trialParams(config).values();
        List<Replay> out = new ArrayList<>();
        for (Param p : config.params()) {
            for (int sign : new int[] {-1, 1}) {
                Map<String, Double> moved = new LinkedHashMap<>(base);
                moved.put(p.name(), base.get(p.name()) + sign * NUDGE * (p.high() - p.low()));
                out.add(new Replay(p.name() + (sign < 0 ? " -1%" : " +1%"), moved, false));
            }
        }
        out.add(new Replay("other mesh", base, true));
        return out;
    }

    private static ObjectNode replay(Replay r, CardSleight same, CardSleight otherMesh, StudyConfig config) {
        ObjectNode o = Json.mapper().createObjectNode();
        o.put("label", r.label());
        ObjectNode params = o.putObject("params");
        r.params().forEach(params::put);
        o.put("mesh", (r.otherMesh() ? otherMesh : same).meshName());
        try {
            CardSleight.Outcome out = (r.otherMesh() ? otherMesh : same).run(r.params(), null);
            ArrayNode values = o.putArray("values");
            for (double v : out.values()) {
                values.add(v);
            }
            boolean meets = config.meets(out.values());
            o.put("meetsTolerances", meets);
            o.put("minGap", out.cost().minGap());
            o.put("wallSeconds", out.cost().wallSeconds());
            StringBuilder s = new StringBuilder();
            for (int i = 0; i < config.objectives().size(); i++) {
                s.append(i == 0 ? "" : ", ").append(config.objectives().get(i)).append(' ').append(String.format(Locale.ROOT, "%.4g", out.values()[i]));
            }
            o.put("summary", s + (meets ? " (meets)" : " (misses)"));
        } catch (RuntimeException e) {
            o.put("meetsTolerances", false);
            o.put("error", e.getMessage());
            o.put("summary", "not a valid trial: " + e.getMessage());
        }
        return o;
    }
}
