package handsim.app;

import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * The card trial that {@code view} and {@code export} show instead of the hand: {@code --scene
 * snap|double-lift} with a recorded {@code --trajectory} or a study's chosen trial ({@code
 * --study}).
 */
final class CardsSceneChoice {

    @Option(names = "--scene", paramLabel = "NAME", description = "snap or double-lift: a card trial (thesis 4.2.4, 4.2.5) instead of the hand")
    String scene;

    @Option(names = "--trajectory", paramLabel = "FILE", description = "with --scene: the trajectory.json of `cards snap|lift --out` "
            + "(view without it runs the configured Card Snapping trial with coarse fingertips first)")
    Path trajectory;

    @Option(names = "--study", paramLabel = "DIR", description = "with --scene: the chosen trial of a `cards optimize` study folder")
    Path study;

    boolean given() {
        return scene != null;
    }

    /** Checks the choice; the trajectory file to show, or null (view only: run the default snap trial). */
    Path file(boolean required) {
        if (!handsim.cards.sleight.Sleights.NAMES.contains(scene)) {
            throw new IllegalArgumentException("--scene must be one of " + String.join(", ", handsim.cards.sleight.Sleights.NAMES)
                    + ", got \"" + scene + "\"");
        }
        if (trajectory != null && study != null) {
            throw new IllegalArgumentException("--trajectory and --study: give one of them");
        }
        if (study != null) {
            return chosenTrajectory(study);
        }
        if (trajectory != null && !Files.isRegularFile(trajectory)) {
            throw new IllegalArgumentException("--trajectory " + trajectory + " is not a file");
        }
        if (trajectory == null && (required || !scene.equals("snap"))) {
            throw new IllegalArgumentException("--scene " + scene + " needs --trajectory FILE or --study DIR");
        }
        return trajectory;
    }

    /** The trajectory of a study's chosen trial, as {@code cards optimize} records it (best/ in folders of older studies). */
    static Path chosenTrajectory(Path study) {
        for (String dir : new String[] {CardsOptimize.CHOSEN_DIR, "best"}) {
            Path file = study.resolve(dir).resolve("trajectory.json");
            if (Files.isRegularFile(file)) {
                return file;
            }
        }
        throw new IllegalArgumentException("--study " + study + " holds no " + CardsOptimize.CHOSEN_DIR
                + "/trajectory.json (is it a study folder of cards optimize, run to its end?)");
    }
}
