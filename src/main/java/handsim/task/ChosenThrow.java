package handsim.task;

import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;

/**
 * The throw policy of a controller whose throws are chosen outside it, before the episode goes
 * on (by the {@link ThrowPlanner}, or by a learner's step): each throw is set just before the
 * controller asks for it, and is used once.
 */
public final class ChosenThrow implements ThrowPolicy {

    private ThrowParameters next;

    /** The throw the controller makes when it next asks. */
    public void set(ThrowParameters parameters) {
        next = parameters;
    }

    @Override
    public ThrowParameters decide(Observation observation) {
        if (next == null) {
            throw new IllegalStateException("the controller asked for a throw that was not chosen");
        }
        ThrowParameters p = next;
        next = null;
        return p;
    }
}
