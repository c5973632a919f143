package handsim.learn;

import handsim.config.Json;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Imitation of a teacher by dataset aggregation (DAgger, Ross, Gordon and Bagnell 2011): the
 * {@code seed}, {@code dagger}, {@code ddpg} and {@code pretrain} sections of a DAgger config
 * ({@code configs/train/flip-dagger.json}; every field in {@code configs/train/README.md}).
 *
 * @param seed root seed of the episodes, the teacher's searches and the fits
 * @param rounds DAgger rounds: each plays {@code episodesPerRound} episodes with the learner fitted
 *     after the round before (the first with the initial actor), labels every decision, and fits
 *     a fresh actor to all labels so far
 * @param episodesPerRound episodes per round
 * @param maxDecisionsPerEpisode an episode is cut off after this many decisions
 * @param executeLabel where the learner's action fails and the teacher found one that works, the
 *     episode goes on with the teacher's (so the states stay the learner's where it is right);
 *     false: always with the learner's own
 * @param weighting {@link Weighting#UNIFORM}, or {@link Weighting#ROBUSTNESS}: each example
 *     weighs its label's robustness
 * @param minRobustness labels less robust than this are left out of the fit
 * @param refit {@link Refit#FRESH}: each round fits a fresh actor; {@link Refit#CONTINUE}: the
 *     round's fit starts from the actor that played it (when it is a network), its normaliser's
 *     statistics counting as {@code pretrain.policyObservations} observations, so that a fit does
 *     not lose the precision of the actor it improves on where the labels agree with it
 * @param network the actor's layers and input normalisation ({@code ddpg} section, so that DDPG can
 *     fine-tune the result; its other fields are unused here)
 * @param fit the regression of each round ({@code pretrain} section: epochs, batch size, learning
 *     rate, held-out share)
 */
public record DaggerConfig(long seed, int rounds, int episodesPerRound, int maxDecisionsPerEpisode, boolean executeLabel,
        Weighting weighting, double minRobustness, Refit refit, LearnerConfig.Ddpg network, LearnerConfig.Pretrain fit) {

    /** Where each round's fit starts. */
    public enum Refit {
        FRESH, CONTINUE;

        String label() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /** How each example weighs in the fit. */
    public enum Weighting {
        UNIFORM, ROBUSTNESS;

        String label() {
            return name().toLowerCase(Locale.ROOT);
        }

        static Weighting parse(Json j, String field) {
            String v = j.string(field);
            for (Weighting w : values()) {
                if (w.label().equals(v)) {
                    return w;
                }
            }
            throw j.fieldError(field, "must be uniform or robustness, got \"" + v + "\"");
        }
    }

    public static DaggerConfig load(Path file) {
        return parse(Json.load(file));
    }

    /** The four sections of {@code j}; other sections are left to the caller. */
    public static DaggerConfig parse(Json j) {
        Json d = j.get("dagger");
        d.allow("comment");
        String refit = d.string("refit", Refit.FRESH.label());
        if (!refit.equals(Refit.FRESH.label()) && !refit.equals(Refit.CONTINUE.label())) {
            throw d.fieldError("refit", "must be fresh or continue, got \"" + refit + "\"");
        }
        DaggerConfig c = new DaggerConfig(j.longValue("seed"), d.integer("rounds", 1, 1000), d.integer("episodesPerRound", 1, 1_000_000),
                d.integer("maxDecisionsPerEpisode", 1, 100_000), d.bool("executeLabel", true), Weighting.parse(d, "weighting"),
                d.number("minRobustness", 0, 1), refit.equals(Refit.CONTINUE.label()) ? Refit.CONTINUE : Refit.FRESH,
                LearnerConfig.Ddpg.parse(j.get("ddpg")), LearnerConfig.Pretrain.parse(j.get("pretrain")));
        if (c.refit == Refit.CONTINUE && c.fit.policyObservations() == 0) {
            throw d.fieldError("refit", "continue needs pretrain.policyObservations, how many observations the actor's "
                    + "normaliser statistics count as");
        }
        d.requireNoUnknownFields();
        return c;
    }
}
