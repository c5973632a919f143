package handsim.cards.sim;

import handsim.config.Json;

/**
 * What one card simulation (a trial, or the hold it starts from) may use before it is stopped
 * and counted failed ({@link handsim.cards.contact.BudgetExceeded}), from
 * configs/cards/budget.json: memory for contacts (spatial-hash cell entries and candidate pairs
 * per broad-phase query), Newton iterations per simulated second, and wall time. A trial within
 * physical ranges stays far inside them; they keep an absurd one (a bone moving at 1e6 m/s, a
 * stiff case where Newton never converges) from exhausting the machine or a study's night.
 *
 * @param maxHashEntries  (cell, id) entries of one spatial hash (8 bytes each, plus its cell table)
 * @param maxContactPairs candidate contact pairs of one broad-phase query
 * @param maxNewtonIterationsPerSecond Newton iterations per simulated second (the thesis-resolution trial takes about 665)
 * @param maxWallSeconds  wall time of one simulation (s)
 */
public record TrialBudget(long maxHashEntries, long maxContactPairs, double maxNewtonIterationsPerSecond, double maxWallSeconds) {

    /** No limits: for tests and tools that build scenes by hand. */
    public static final TrialBudget UNLIMITED = new TrialBudget(Integer.MAX_VALUE, Integer.MAX_VALUE, Double.POSITIVE_INFINITY,
            Double.POSITIVE_INFINITY);

    /** Reads configs/cards/budget.json; each limit must lie in a range that still lets a thesis-resolution trial run. */
    public static TrialBudget parse(Json j) {
        j.allow("comment", "fields");
        TrialBudget b = new TrialBudget((long) j.number("maxHashEntries", 1e4, 1e9), (long) j.number("maxContactPairs", 1e3, 1e9),
                j.number("maxNewtonIterationsPerSecond", 1, 1e7), j.number("maxWallSeconds", 1, 1e6));
        j.requireNoUnknownFields();
        return b;
    }

    /** The most Newton iterations a simulation of {@code seconds} simulated seconds may take. */
    public long newtonIterationsFor(double seconds) {
        double n = Math.ceil(maxNewtonIterationsPerSecond * seconds);
        return n >= Long.MAX_VALUE ? Long.MAX_VALUE : (long) n;
    }

    /** As JSON, for a study's record of what its trials were run with. */
    public com.fasterxml.jackson.databind.node.ObjectNode toJson() {
        com.fasterxml.jackson.databind.node.ObjectNode o = Json.mapper().createObjectNode();
        o.put("maxHashEntries", maxHashEntries);
        o.put("maxContactPairs", maxContactPairs);
        o.put("maxNewtonIterationsPerSecond", maxNewtonIterationsPerSecond);
        o.put("maxWallSeconds", maxWallSeconds);
        return o;
    }
}
