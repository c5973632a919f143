package handsim.app;

import handsim.cards.sleight.CardSleight;
import handsim.cards.sleight.Sleights;
import handsim.cards.study.StudyConfig;
import handsim.config.Home;
import handsim.config.Json;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code handsim cards}: the soft-body card sleights (thesis sec. 3.2 and 4.2). */
@Command(name = "cards", mixinStandardHelpOptions = true,
        description = "Soft fingertips handle thin-shell playing cards (thesis 3.2, 4.2).",
        subcommands = {CardsCommand.Snap.class, CardsCommand.Lift.class, CardsOptimize.class, CardsRobust.class})
final class CardsCommand implements Runnable {

    @Override
    public void run() {
        new picocli.CommandLine(this).usage(System.out);
    }

    /** Where the rested stacks of Double Lift are kept, shared by every trial and study of the project. */
    static Path checkpoints() {
        return Home.resolve("runs/cards-checkpoints");
    }

    /** The sleight {@code name} of the project's configs with the scene options and {@code --set} overrides. */
    static CardSleight sleight(String name, CardsSceneOptions scene, Map<String, String> overrides) {
        if (!Sleights.NAMES.contains(name)) {
            throw new IllegalArgumentException("--sleight must be one of " + String.join(", ", Sleights.NAMES) + ", got \"" + name + "\"");
        }
        CardSleight s = Sleights.fromConfigs(name, Home.root(), scene.mesh, scene.card, overrides, checkpoints());
        if (s instanceof handsim.cards.sleight.LiftTrial lift) {
            lift.withLog(System.out::println);
        }
        return s;
    }

    /** The study config of a sleight: configs/cards/NAME-study.json. */
    static Path studyConfig(String name) {
        return Home.resolve("configs/cards/" + name + "-study.json");
    }

    /** One trial of a sleight: {@code cards snap}, {@code cards lift}. */
    abstract static class TrialCommand implements Callable<Integer> {

        @Option(names = "--params", paramLabel = "FILE", description = "JSON with the trial's parameters (default: the params of the sleight's config)")
        Path params;

        @Option(names = "--out", paramLabel = "DIR", description = "folder for result.json, trajectory.json, frames/ and strip.png (default: none written)")
        Path out;

        @Option(names = "--set", paramLabel = "FILE.KEY=VALUE", description = "override a field of configs/cards/FILE.json (the sleight's, materials, solver), "
                + "e.g. --set solver.parallel=false (repeatable; dotted paths)")
        List<String> overrides = List.of();

        @Mixin
        CardsSceneOptions scene;

        abstract String sleightName();

        @Override
        public Integer call() throws IOException {
            scene.checkFrameSize();
            new OutputPaths().heldFolder("--out", out, CardsRecording.RECORDING).check();
            CardSleight sleight = sleight(sleightName(), scene, RunOptions.keyValues(overrides));
            if (params != null && !Files.isRegularFile(params)) {
                throw new IllegalArgumentException("--params " + params + " is not a file");
            }
            Map<String, Double> p = params == null ? sleight.defaults() : sleight.parseParams(Json.load(params));
            System.out.printf(Locale.ROOT, "handsim cards %s: %s, %s fingertips, %d nodes (%d free), %s cards%n", sleightName(), sleight.title(),
                    sleight.meshName(), sleight.world().nodeCount(), sleight.world().freeNodeCount(), sleight.inputs().get("card").asText());
            long h0 = System.nanoTime();
            sleight.startState(p);
            System.out.printf(Locale.ROOT, "start (warm-up checkpoint): %.1f s wall%n", (System.nanoTime() - h0) * 1e-9);
            CardsRecording.Recorded run = CardsRecording.record(sleight, p);
            CardsRecording.report(run.outcome());
            if (out != null) {
                List<String> names = StudyConfig.load(studyConfig(sleightName())).objectives();
                CardsRecording.write(out, run, CardsRecording.resultJson(sleight, p, run, names), CardViews.of(sleightName(), ViewerSession.config()),
                        scene.frameWidth(), scene.height);
            }
            return 0;
        }
    }

    /** {@code handsim cards snap}: one Card Snapping trial. */
    @Command(name = "snap", mixinStandardHelpOptions = true,
            description = "Run one Card Snapping trial (thesis 4.2.4): print the end angle between the cards, the objective, "
                    + "the smallest gap, Newton iterations and wall time; write the trajectory and PNG frames to --out.")
    static final class Snap extends TrialCommand {
        @Override
        String sleightName() {
            return "snap";
        }
    }

    /** {@code handsim cards lift}: one Double Lift trial. */
    @Command(name = "lift", mixinStandardHelpOptions = true,
            description = "Run one Double Lift trial (thesis 4.2.5): the fingertips pinch the top of a stack of cards and lift; print "
                    + "the objectives (|h1 - h_target|, |h2 - h_target|, |d3|), the smallest gap, Newton iterations, the wall time and "
                    + "its split; write the trajectory and PNG frames to --out. The rested stack is made once and kept in "
                    + "runs/cards-checkpoints.")
    static final class Lift extends TrialCommand {
        @Override
        String sleightName() {
            return "double-lift";
        }
    }
}
