package handsim.control;

import java.util.function.BiPredicate;
import java.util.function.Predicate;

/**
 * Chooses the parameters of a THROW when the controller enters that state (sec. 3.7): the
 * nominal policy looks them up per desired height, a learned policy evaluates its actor.
 */
@FunctionalInterface
public interface ThrowPolicy {

    ThrowParameters decide(Observation observation);

    /**
     * The episode's throw number {@code throwIndex} (1: the first, made from the object caught out
     * of the launch; 2: the one after the hand's own first catch, ...). The same as {@link
     * #decide(Observation)} unless the policy has an {@link #withOpening opening} or a {@link #withSpecialAt special} policy.
     */
    default ThrowParameters decide(Observation observation, int throwIndex) {
        return decide(observation);
    }

    /**
     * {@code opening} for each episode's first throw and {@code later} for every later one: the
     * thrown-in object rests in the hand otherwise than one the hand caught from its own throw.
     */
    static ThrowPolicy withOpening(ThrowPolicy opening, ThrowPolicy later) {
        return switching(later, (observation, throwIndex) -> throwIndex == 1, opening);
    }

    /**
     * {@code special} for the throws after the first whose decision {@code where} accepts (a rest
     * of the object in the hand that this policy throws badly from), this policy otherwise.
     */
    default ThrowPolicy withSpecialAt(Predicate<Observation> where, ThrowPolicy special) {
        return switching(this, (observation, throwIndex) -> throwIndex > 1 && where.test(observation), special);
    }

    /** {@code other} at the decisions {@code useOther} accepts (given the throw number), {@code usual} at all others and when asked without a number. */
    private static ThrowPolicy switching(ThrowPolicy usual, BiPredicate<Observation, Integer> useOther, ThrowPolicy other) {
        return new ThrowPolicy() {
            @Override
            public ThrowParameters decide(Observation observation) {
                return usual.decide(observation);
            }

            @Override
            public ThrowParameters decide(Observation observation, int throwIndex) {
                return useOther.test(observation, throwIndex) ? other.decide(observation) : usual.decide(observation, throwIndex);
            }
        };
    }
}
