package handsim.control;

/**
 * Chooses the parameters of a THROW when the controller enters that state (sec. 3.7): the
 * nominal policy looks them up per desired height, a learned policy evaluates its actor.
 */
@FunctionalInterface
public interface ThrowPolicy {

    ThrowParameters decide(Observation observation);
}
