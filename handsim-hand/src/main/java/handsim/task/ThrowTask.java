package handsim.task;

import handsim.control.ControllerConfig;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.sim.Simulator;

/**
 * One of the paper's tasks (sec. 4): what each throw aims at, the nominal (hand-tuned) throw for
 * it, how a loop is scored and what counts as success. The goal is part of the learner's state
 * (sec. 3.7: "we embed the goal to the state vector"). A task is stateful over an episode (its
 * current goal) and used by one thread at a time.
 */
public interface ThrowTask {

    /** {@code height}, {@code box} or {@code flip}. */
    String name();

    /** Number of goal entries appended to the state. */
    int goalSize();

    /**
     * Refuses this task to {@code user} (a throw planner, a teacher) when its goal changes from
     * throw to throw: a twin episode restored from a checkpoint does not carry the task's goal.
     */
    default void requireFixedGoal(String user) {
        if (goalSize() != 0) {
            throw new IllegalArgumentException("the " + user + " needs a task whose goal stays the same from throw to throw "
                    + "(flip); the " + name() + " task's changes");
        }
    }

    /**
     * Begins an episode in a world that was just reset: draws the episode's goals from
     * {@code seed} and adds the task's scenery (the box) to {@code sim}.
     */
    void start(Simulator sim, long seed);

    /** The goal of the next throw (or of the throw in progress, until {@link #advance}), as state entries. */
    double[] goal();

    /** A throw was just made: the following one aims at its own goal. */
    void advance();

    /** The hand-tuned throw parameters for the current goal (the nominal controller's THROW). */
    ThrowParameters nominalThrow();

    /**
     * The box of throw parameters the learner's actions map onto for this task: the
     * controller's ({@code fallback}) unless the task needs another.
     */
    default ThrowSpace throwSpace(ThrowSpace fallback) {
        return fallback;
    }

    /**
     * The controller settings this task's episodes run with: {@code base} unless the task needs
     * its own (the flip task may let go of a throw by the object's predicted turn).
     */
    default ControllerConfig controller(ControllerConfig base) {
        return base;
    }

    /** The reward of a finished throw loop (loop index >= 1): the paper's eq. (5), (6) or (7). */
    double reward(LoopRecord loop);

    /** Whether a finished throw loop did what the task asks (and the object was caught). */
    boolean success(LoopRecord loop);

    /**
     * Whether another way of catching could have made a success of a throw loop that failed: by
     * default every throw; a throw planner tries other catches only where this says so.
     */
    default boolean catchMayMatter(LoopRecord loop) {
        return true;
    }

    /** The apex height the current throw aims at, for the loop record (NaN without a height goal). */
    default double targetHeight() {
        return Double.NaN;
    }
}
