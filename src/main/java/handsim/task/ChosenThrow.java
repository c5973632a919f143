package handsim.task;

import handsim.control.CatchStyle;
import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import java.util.Optional;

/**
 * The throw policy of a controller whose throws are chosen outside it, before the episode goes
 * on (by the {@link ThrowPlanner}, or by a learner's step): each throw is set just before the
 * controller asks for it, and is used once; the planner may set how its catch meets the object.
 */
public final class ChosenThrow implements ThrowPolicy {

    private ThrowParameters next;
    private CatchStyle nextCatch;
    private CatchStyle decidedCatch;

    /** The throw the controller makes when it next asks; its catch as the controller catches thrown objects. */
    public void set(ThrowParameters parameters) {
        set(parameters, null);
    }

    /** The throw the controller makes when it next asks, and how its catch meets the object (null: as the controller's). */
    public void set(ThrowParameters parameters, CatchStyle catching) {
        next = parameters;
        nextCatch = catching;
    }

    @Override
    public Optional<CatchStyle> catchAfterThrow() {
        return Optional.ofNullable(decidedCatch);
    }

    @Override
    public ThrowParameters decide(Observation observation) {
        if (next == null) {
            throw new IllegalStateException("the controller asked for a throw that was not chosen");
        }
        ThrowParameters p = next;
        decidedCatch = nextCatch;
        next = null;
        nextCatch = null;
        return p;
    }
}
