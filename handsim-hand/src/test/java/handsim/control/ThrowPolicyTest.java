package handsim.control;

import static org.junit.jupiter.api.Assertions.assertSame;

import handsim.math.Vec3;
import org.junit.jupiter.api.Test;

/** A policy with an opening: which of the two chooses each throw of an episode. */
class ThrowPolicyTest {

    private static final ThrowParameters OPENING = new ThrowParameters(Vec3.ZERO, Vec3.ZERO, 0.1);
    private static final ThrowParameters REST = new ThrowParameters(Vec3.ZERO, Vec3.ZERO, 0.2);

    /** Throw 1 (from the thrown-in object) is the opening's, every later throw the other policy's. */
    @Test
    void theOpeningMakesTheFirstThrowOnly() {
        ThrowPolicy p = ThrowPolicy.withOpening(obs -> OPENING, obs -> REST);
        assertSame(OPENING, p.decide(null, 1));
        assertSame(REST, p.decide(null, 2));
        assertSame(REST, p.decide(null, 37));
        assertSame(REST, p.decide(null), "asked without a throw number, the policy of the loop answers");
    }

    /** A plain policy answers the same whatever the throw number. */
    @Test
    void aPlainPolicyIgnoresTheThrowNumber() {
        ThrowPolicy p = obs -> REST;
        assertSame(REST, p.decide(null, 1));
        assertSame(REST, p.decide(null, 2));
    }

    /**
     * A special policy throws where its test accepts the decision, and never the first throw
     * (made from the thrown-in object, not from a rest the hand's own catch left).
     */
    @Test
    void aSpecialPolicyThrowsWhereItsTestAcceptsAfterTheFirstThrowOnly() {
        ThrowParameters special = new ThrowParameters(Vec3.ZERO, Vec3.ZERO, 0.3);
        Observation flat = new Observation(1, new double[0], new double[0], null, Vec3.ZERO, null, 0);
        Observation other = new Observation(2, new double[0], new double[0], null, Vec3.ZERO, null, 0);
        ThrowPolicy p = ThrowPolicy.withOpening(obs -> OPENING, obs -> REST).withSpecialAt(obs -> obs == flat, obs -> special);
        assertSame(OPENING, p.decide(flat, 1), "the first throw stays the opening's");
        assertSame(special, p.decide(flat, 2));
        assertSame(special, p.decide(flat, 40));
        assertSame(REST, p.decide(other, 2));
        assertSame(REST, p.decide(flat), "asked without a throw number, the usual policy answers");
    }
}
