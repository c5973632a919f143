package handsim.control;

import java.util.Optional;

/**
 * Chooses the parameters of a THROW when the controller enters that state (sec. 3.7): the
 * nominal policy looks them up per desired height, a learned policy evaluates its actor.
 */
@FunctionalInterface
public interface ThrowPolicy {

    ThrowParameters decide(Observation observation);

    /**
     * How the catch after the throw last decided should meet the object; empty (a policy's usual
     * answer): as the controller catches thrown objects. A throw planner chooses it with the throw.
     */
    default Optional<CatchStyle> catchAfterThrow() {
        return Optional.empty();
    }
}
