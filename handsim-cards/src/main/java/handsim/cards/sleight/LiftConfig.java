package handsim.cards.sleight;

import handsim.config.Json;

/**
 * The Double Lift scene from configs/cards/double-lift.json (thesis 4.2.5), validated field by
 * field: the card, the fingertips and their starting gap to the stack's ends, the stack (how
 * many cards, how many of the top ones move in a trial, the warm-up that brings it to rest) and
 * the trial (duration, h_target, how long the lifted pair must then rest in the fingers).
 *
 * @param initialGap    gap between each fingertip's skin and the cards' ends at the start (m)
 * @param count         cards in the stack
 * @param freeCards     top cards that move in a trial; the deck below lies still where the warm-up
 *                      left it
 * @param warmupLimit   longest warm-up (s) before a stack that is still moving is an error
 * @param restSpeed     the stack is at rest when no node moves faster than this (m/s) ...
 * @param restSteps     ... for this many steps in a row
 * @param duration      simulated time of a trial (s)
 * @param hTarget       how far the top two cards should end above where they lay (m)
 * @param restAfterLift the lift ends at least this long before the trial does (s)
 */
public record LiftConfig(CardSpec card, FingertipSpec fingertip, double initialGap, int count, int freeCards, double warmupLimit,
                         double restSpeed, int restSteps, double duration, double hTarget, double restAfterLift, int frameEvery,
                         LiftParams defaults) {

    public static LiftConfig parse(Json j, String meshOverride) {
        j.allow("comment", "solver"); // the solver.json fields the sleight sets (SleightFiles)
        Json card = j.get("card");
        CardSpec cardSpec = CardSpec.parse(card);
        Json tip = j.get("fingertip");
        FingertipSpec tipSpec = FingertipSpec.parse(tip, meshOverride);
        double initialGap = tip.number("initialGap", 0, 0.01);
        Json stack = j.get("stack");
        stack.allow("comment");
        int count = stack.integer("count", 3, 200);
        int free = stack.integer("freeCards", 3, count);
        Json trial = j.get("trial");
        trial.allow("comment");
        double duration = trial.number("duration", 0.01, 100);
        double rest = trial.number("restAfterLift", 0, duration);
        LiftParams defaults = LiftParams.parse(j.get("params"));
        defaults.validate(duration - rest, j.source() + ": params");
        LiftConfig c = new LiftConfig(cardSpec, tipSpec, initialGap, count, free, stack.number("warmupLimit", 0.01, 100),
                stack.number("restSpeed", 1e-9, 1), stack.integer("restSteps", 1, 10_000), duration,
                trial.number("hTarget", 0, 1), rest, trial.integer("frameEvery", 1, 10_000), defaults);
        for (Json node : new Json[] {card, tip, stack, trial, j}) {
            node.requireNoUnknownFields();
        }
        return c;
    }

    /** The latest end of the lift: the pair then rests in the fingers until the trial ends (s). */
    public double lastLiftEnd() {
        return duration - restAfterLift;
    }

    public String meshName() {
        return fingertip.meshName();
    }
}
