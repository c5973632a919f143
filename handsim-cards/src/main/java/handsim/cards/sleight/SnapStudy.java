package handsim.cards.sleight;

import handsim.cards.contact.BudgetExceeded;
import handsim.cards.study.Evaluation;
import handsim.cards.study.Objective;
import handsim.cards.study.StudyConfig;
import handsim.cards.study.TrialParams;
import handsim.cards.tpe.Param;
import handsim.config.ConfigException;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * Card Snapping as the objective of a study (thesis 4.2.4, Fig. 4.9): a trial per suggested
 * bone trajectory, minimising |α_target − α_end| in degrees (a dropped card scores the largest
 * error), with the end angle, the card drop, the smallest gap, Newton iterations and the time
 * split kept in each trial's record.
 */
public final class SnapStudy {

    /** The decision variables, by name, as the study config must list them. */
    public static final List<String> PARAMS = List.of("t0", "t1", "vp", "t2", "t3", "vs");

    private SnapStudy() {
    }

    /**
     * Requires a search space every point of which is a valid trial: one objective, the six
     * parameters (float, linear), windows that cannot overlap (t1's low ≥ t0's high, t2's low ≥
     * t1's high, t3's low ≥ t2's high), t3's high within the trial's {@code duration}, speeds in
     * [0, {@link SnapParams#MAX_SPEED}].
     * The error names {@code source}, the field and the values.
     */
    public static void check(StudyConfig c, double duration, String source) {
        if (c.objectives().size() != 1) {
            throw new ConfigException(source + ": objectives: Card Snapping has one objective, got " + c.objectives());
        }
        List<String> names = c.params().stream().map(Param::name).toList();
        if (!names.stream().sorted().toList().equals(PARAMS.stream().sorted().toList())) {
            throw new ConfigException(source + ": params: Card Snapping searches " + PARAMS + ", got " + names);
        }
        Map<String, Param> p = c.params().stream().collect(Collectors.toMap(Param::name, Function.identity()));
        for (Param q : c.params()) {
            if (q.log() || q.integer()) {
                throw new ConfigException(source + ": params: " + q.name() + " must be a linear float (no log, no int)");
            }
        }
        order(p.get("t0"), p.get("t1"), source, "the pinch could end before it starts");
        order(p.get("t1"), p.get("t2"), source, "the slide could start before the pinch ends");
        order(p.get("t2"), p.get("t3"), source, "the slide could end before it starts");
        if (p.get("t0").low() < 0) {
            throw new ConfigException(source + ": params: t0's low must be >= 0, got " + p.get("t0").low());
        }
        if (p.get("t3").high() > duration) {
            throw new ConfigException(source + ": params: t3's high " + p.get("t3").high() + " is beyond the trial's duration " + duration + " s");
        }
        for (String speed : List.of("vp", "vs")) {
            if (p.get(speed).low() < 0) {
                throw new ConfigException(source + ": params: " + speed + "'s low must be >= 0, got " + p.get(speed).low());
            }
            if (p.get(speed).high() > SnapParams.MAX_SPEED) {
                throw new ConfigException(source + ": params: " + speed + "'s high must be <= " + SnapParams.MAX_SPEED
                        + " m/s (a flick of the finger), got " + p.get(speed).high());
            }
        }
    }

    private static void order(Param first, Param second, String source, String why) {
        if (second.low() < first.high()) {
            throw new ConfigException(source + ": params: " + second.name() + "'s low " + second.low() + " is below " + first.name()
                    + "'s high " + first.high() + ": " + why);
        }
    }

    /** The trial's parameters as a bone trajectory. */
    public static SnapParams params(TrialParams p) {
        return new SnapParams(p.get("t0"), p.get("t1"), p.get("vp"), p.get("t2"), p.get("t3"), p.get("vs"));
    }

    /** The objective a study calls from its workers: one trial of {@code trial} per suggestion; a trial past its budget fails, saying which. */
    public static Objective objective(SnapTrial trial) {
        return p -> {
            try {
                return evaluation(trial.run(params(p)));
            } catch (BudgetExceeded e) {
                throw new Objective.TrialFailed("past its budget: " + e.getMessage(), e);
            }
        };
    }

    /** A trial's objective value and the figures kept with it. */
    static Evaluation evaluation(SnapResult r) {
        return Evaluation.of(r.objective())
                .with("alphaEnd", r.alphaEnd())
                .with("minGap", r.minGap())
                .with("cardDrop", r.cardDrop())
                .with("held", r.held() ? 1 : 0)
                .with("newtonIterations", r.newtonIterations())
                .with("wallSeconds", r.wallSeconds())
                .with("assemblySeconds", r.assemblySeconds())
                .with("contactSeconds", r.contactSeconds())
                .with("solveSeconds", r.solveSeconds());
    }
}
