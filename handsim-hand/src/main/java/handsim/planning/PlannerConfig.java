package handsim.planning;

import handsim.config.Json;
import handsim.control.CatchStyle;
import java.util.List;

/**
 * {@code configs/planner.json}: how the {@link ThrowPlanner} searches.
 *
 * @param rounds the search's rounds in order; the first try of the first is the policy's own
 *     throw; a round after the first begins only when no earlier try was a success leading on
 * @param goodAlignment |long axis . palm z| after the catch at which a successful try ends the search
 * @param lookahead throws tried at most from a successful try's next state (the policy's, then
 *     variations by the spread of round 1; the first that succeeds is tried first when the live
 *     hand reaches that state); the try counts as a dead end when none succeeds;
 *     0: no lookahead
 * @param catchStyles how the catch after a tried throw meets the object, in turn: a decision's
 *     try k (and the lookahead's try k from each next state) is caught with style k mod their
 *     number; none: every catch as the controller's own
 * @param throwInStyles ways to catch the episode's throw-in tried after the controller's own, in
 *     order, until one holds the object and (with a lookahead) leads on ({@link
 *     ThrowPlanner#chooseThrowInCatch}); none: the throw-in is caught as the controller's own, untried
 * @param catchBranches other ways to catch a tried throw that turned the object far enough but
 *     was no success leading on: the throw is played once and its catch played again from where
 *     THROW ends with each of these in order, until one is; the lookahead's
 *     throws likewise; none: each throw is caught one way
 * @param lookaheadDepth with a lookahead, how many throws in a row from a try's next state must
 *     succeed for it to lead on: 1, a throw from its next state succeeds; 2, and a throw from
 *     that one's next state too (each found among up to {@code lookahead} throws), and so on
 */
public record PlannerConfig(List<Round> rounds, double goodAlignment, int lookahead, List<CatchStyle> catchStyles,
        List<CatchStyle> throwInStyles, List<CatchStyle> catchBranches, int lookaheadDepth) {

    /**
     * One round of the search: up to {@code candidates} throws, each the proposal varied by a
     * Gaussian of standard deviation {@code spread} in the policy's action units ([-1, 1] per
     * entry); with {@code catchStyles}, the round's try c is caught with style c mod their number
     * (instead of as the config's {@link PlannerConfig#catchStyles} say).
     */
    public record Round(int candidates, double spread, List<CatchStyle> catchStyles) {

        public Round {
            catchStyles = List.copyOf(catchStyles);
        }

        /** A round whose tries are caught as the config says. */
        public Round(int candidates, double spread) {
            this(candidates, spread, List.of());
        }

        static Round parse(Json j) {
            Round r = new Round(j.integer("candidates", 1, 10000), j.number("spread", 0, 2), styles(j, "catchStyles"));
            j.requireNoUnknownFields();
            return r;
        }
    }


    public PlannerConfig {
        rounds = List.copyOf(rounds);
        catchStyles = List.copyOf(catchStyles);
        throwInStyles = List.copyOf(throwInStyles);
        catchBranches = List.copyOf(catchBranches);
        if (rounds.isEmpty()) {
            throw new IllegalArgumentException("a planner needs at least one round");
        }
    }

    /** Settings whose tries are all caught as the controller's own. */
    public PlannerConfig(List<Round> rounds, double goodAlignment, int lookahead) {
        this(rounds, goodAlignment, lookahead, List.of(), List.of(), List.of(), 1);
    }

    /** These settings with {@code branches} as their {@link #catchBranches}. */
    public PlannerConfig withCatchBranches(List<CatchStyle> branches) {
        return new PlannerConfig(rounds, goodAlignment, lookahead, catchStyles, throwInStyles, branches, lookaheadDepth);
    }

    /** These settings with a lookahead of {@code depth} throws in a row ({@link #lookaheadDepth}). */
    public PlannerConfig withLookaheadDepth(int depth) {
        return new PlannerConfig(rounds, goodAlignment, lookahead, catchStyles, throwInStyles, catchBranches, depth);
    }

    /** How many throws in a row a try's lookahead plays: 0 without a lookahead. */
    int depth() {
        return lookahead == 0 ? 0 : lookaheadDepth;
    }

    /** The file's own settings: those of an object without an entry under {@code objects}. */
    public static PlannerConfig parse(Json j) {
        return parse(j, null);
    }

    /**
     * The settings for {@code object}: the file's {@code rounds}, {@code goodAlignment}, {@code
     * lookahead}, {@code lookaheadDepth}, {@code catchStyles}, {@code throwInStyles} and {@code
     * catchBranches}, each replaced by the one under {@code objects.<object>} when that entry
     * has it (every object's entry is checked, whichever object is planned).
     */
    public static PlannerConfig parse(Json j, String object) {
        j.allow("comment");
        PlannerConfig file = new PlannerConfig(rounds(j), j.number("goodAlignment", 0, 1), lookahead(j), styles(j, "catchStyles"),
                styles(j, "throwInStyles"), styles(j, "catchBranches"), lookaheadDepth(j, 1));
        PlannerConfig chosen = file;
        if (j.has("objects")) {
            Json objects = j.get("objects");
            for (String name : objects.fieldNames()) {
                Json entry = objects.get(name);
                entry.allow("comment");
                PlannerConfig own = new PlannerConfig(entry.has("rounds") ? rounds(entry) : file.rounds(),
                        entry.has("goodAlignment") ? entry.number("goodAlignment", 0, 1) : file.goodAlignment(),
                        entry.has("lookahead") ? lookahead(entry) : file.lookahead(),
                        entry.has("catchStyles") ? styles(entry, "catchStyles") : file.catchStyles(),
                        entry.has("throwInStyles") ? styles(entry, "throwInStyles") : file.throwInStyles(),
                        entry.has("catchBranches") ? styles(entry, "catchBranches") : file.catchBranches(),
                        lookaheadDepth(entry, file.lookaheadDepth()));
                entry.requireNoUnknownFields();
                if (name.equals(object)) {
                    chosen = own;
                }
            }
        }
        j.requireNoUnknownFields();
        return chosen;
    }

    private static int lookahead(Json j) {
        return j.integer("lookahead", 0, 10000);
    }

    private static int lookaheadDepth(Json j, int otherwise) {
        return j.has("lookaheadDepth") ? j.integer("lookaheadDepth", 1, 5) : otherwise;
    }

    static List<CatchStyle> styles(Json j, String field) {
        return j.has(field) ? j.array(field).stream().map(CatchStyle::parse).toList() : List.of();
    }

    /** How try {@code k} of a search is caught: null for the controller's own. */
    CatchStyle catchStyle(int k) {
        return catchStyles.isEmpty() ? null : catchStyles.get(k % catchStyles.size());
    }

    private static List<Round> rounds(Json j) {
        List<Json> list = j.array("rounds");
        if (list.isEmpty()) {
            throw j.fieldError("rounds", "needs at least one round, got []");
        }
        return list.stream().map(Round::parse).toList();
    }

    /** The most throws one decision tries (without the lookahead's). */
    public int maxTries() {
        return rounds.stream().mapToInt(Round::candidates).sum();
    }
}
