package handsim.train;

import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import handsim.control.ThrowSpace;
import handsim.learn.Policy;
import handsim.task.StateVector;
import handsim.task.ThrowTask;

/**
 * The learned THROW (sec. 3.7): the actor maps the state and the task's current goal to an
 * action in [-1, 1]^7, which the throw-parameter box turns into (d_offset, r_target, t_open).
 * Deterministic (no exploration noise) and cheap (plain Java).
 */
public final class LearnedThrowPolicy implements ThrowPolicy {

    private final Policy policy;
    private final ThrowSpace space;
    private final ThrowTask task;
    private final StateVector state;

    public LearnedThrowPolicy(Policy policy, ThrowSpace space, ThrowTask task, StateVector state) {
        this.policy = policy;
        this.space = space;
        this.task = task;
        this.state = state;
    }

    @Override
    public ThrowParameters decide(Observation observation) {
        return space.fromAction(policy.act(state.encode(observation, task.goal())));
    }
}
