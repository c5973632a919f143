package handsim.learn;

import java.util.List;

/**
 * A teacher's answer at one decision, as the learner sees it ({@link TeachableEnv#label}).
 *
 * @param action the action to imitate there, in [-1, 1]^k, or null when the teacher found none
 * @param proposalSucceeded the learner's own action succeeded (and is then the label)
 * @param tries what it cost: the teacher's trials at this decision
 * @param robustness how robust a target the label is, in [0, 1]: the share of the teacher's
 *     trials around it that succeeded too (1 when the teacher does not check, 0 without a label)
 * @param trials the teacher's trials in order, when it tells them (else empty): every action it
 *     tried at this decision and how it came out, failures included
 */
public record Demonstration(double[] action, boolean proposalSucceeded, int tries, double robustness, List<Trial> trials) {

    /**
     * One action the teacher tried: whether it succeeded, the task's reward for it, and the task's
     * measures of how it came out ({@code outcome}, named by the environment; NaN where unmeasured).
     */
    public record Trial(double[] action, boolean success, double reward, double[] outcome) {

        public Trial {
            action = action.clone();
            outcome = outcome.clone();
        }
    }

    public Demonstration {
        action = action == null ? null : action.clone();
        trials = List.copyOf(trials);
        if (!(robustness >= 0 && robustness <= 1)) {
            throw new IllegalArgumentException("robustness must be in [0, 1], got " + robustness);
        }
    }

    /** A demonstration without its trials. */
    public Demonstration(double[] action, boolean proposalSucceeded, int tries, double robustness) {
        this(action, proposalSucceeded, tries, robustness, List.of());
    }

    /** Whether the teacher found an action to imitate. */
    public boolean labelled() {
        return action != null;
    }
}
