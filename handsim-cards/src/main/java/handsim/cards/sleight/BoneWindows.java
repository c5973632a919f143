package handsim.cards.sleight;

import handsim.cards.study.StudyConfig;
import handsim.cards.tpe.Param;
import handsim.config.ConfigException;
import handsim.config.Json;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * The two motion windows both sleights give their bones (thesis 4.2.4, 4.2.5): a pinch in
 * [t0, t1] (s) at mean speed vp (m/s), then a second motion in [t2, t3] at mean speed vs (a slide
 * for Card Snapping, a lift for Double Lift). Each window follows a half-cosine ease, so the
 * bones start and stop smoothly and the window's mean speed is its parameter.
 */
public record BoneWindows(double t0, double t1, double vp, double t2, double t3, double vs) {

    /** The windows' parameter names, as studies list them. */
    public static final List<String> NAMES = List.of("t0", "t1", "vp", "t2", "t3", "vs");

    /**
     * The fastest mean bone speed of a trial (m/s): a fingertip flicked as fast as a hand can
     * moves at about 2 m/s, and even that crosses the card's width (63.5 mm) in 0.03 s, three
     * time steps; the searched pinches, slides and lifts stay below 0.05 m/s.
     */
    public static final double MAX_SPEED = 2;

    /** Reads t0, t1, vp, t2, t3, vs of {@code j} (the caller checks for unknown fields). */
    static BoneWindows parse(Json j) {
        return new BoneWindows(j.number("t0"), j.number("t1"), j.number("vp"), j.number("t2"), j.number("t3"), j.number("vs"));
    }

    /** The windows of a trial's parameters by name. */
    static BoneWindows of(Map<String, Double> p) {
        return new BoneWindows(get(p, "t0"), get(p, "t1"), get(p, "vp"), get(p, "t2"), get(p, "t3"), get(p, "vs"));
    }

    static double get(Map<String, Double> p, String name) {
        Double v = p.get(name);
        if (v == null) {
            throw new IllegalArgumentException("no parameter \"" + name + "\" (got " + p.keySet() + ")");
        }
        return v;
    }

    /**
     * Requires 0 ≤ t0 < t1 ≤ t2 < t3 ≤ {@code lastEnd} and speeds in [0, {@link #MAX_SPEED}]; the
     * message names the offending field and value.
     */
    public void validate(double lastEnd, String source) {
        String where = source == null ? "" : source + ": ";
        check(t0 >= 0, where + "t0 must be >= 0, got " + t0);
        check(t1 > t0, where + "t1 must be > t0 = " + t0 + ", got " + t1);
        check(t2 >= t1, where + "t2 must be >= t1 = " + t1 + ", got " + t2);
        check(t3 > t2, where + "t3 must be > t2 = " + t2 + ", got " + t3);
        check(t3 <= lastEnd, where + "t3 must be <= " + lastEnd + " s, got " + t3);
        check(vp >= 0 && vp <= MAX_SPEED, where + "vp must be a speed in [0, " + Json.show(MAX_SPEED) + "] m/s, got " + Json.show(vp));
        check(vs >= 0 && vs <= MAX_SPEED, where + "vs must be a speed in [0, " + Json.show(MAX_SPEED) + "] m/s, got " + Json.show(vs));
    }

    private static void check(boolean ok, String message) {
        if (!ok) {
            throw new IllegalArgumentException(message);
        }
    }

    /** How far the pinch has moved each bone by time t (m). */
    public double pinch(double t) {
        return vp * (t1 - t0) * ease(t, t0, t1);
    }

    /** How far the second motion has moved each bone by time t (m). */
    public double second(double t) {
        return vs * (t3 - t2) * ease(t, t2, t3);
    }

    /** Half-cosine ease from 0 at a to 1 at b (mean slope 1/(b − a)); a step at a if b ≤ a. */
    public static double ease(double t, double a, double b) {
        if (t <= a) {
            return 0;
        }
        if (t >= b) {
            return 1;
        }
        return 0.5 * (1 - Math.cos(Math.PI * (t - a) / (b - a)));
    }

    /** Puts the six fields into {@code m}, in the order of {@link #NAMES}. */
    void putInto(Map<String, Double> m) {
        m.put("t0", t0);
        m.put("t1", t1);
        m.put("vp", vp);
        m.put("t2", t2);
        m.put("t3", t3);
        m.put("vs", vs);
    }

    /**
     * Requires a search space every point of which is a valid trial: exactly {@code names} (the
     * six windows' and the sleight's own), linear floats, windows that cannot overlap (t1's low ≥
     * t0's high, t2's low ≥ t1's high, t3's low ≥ t2's high), t3's high at most {@code lastEnd},
     * speeds ≥ 0. The error names {@code source}, the field and the values.
     */
    static void checkSearchSpace(StudyConfig c, List<String> names, double lastEnd, String sleight, String source) {
        List<String> given = c.params().stream().map(Param::name).toList();
        if (!given.stream().sorted().toList().equals(names.stream().sorted().toList())) {
            throw new ConfigException(source + ": params: " + sleight + " searches " + names + ", got " + given);
        }
        Map<String, Param> p = c.params().stream().collect(Collectors.toMap(Param::name, Function.identity()));
        for (Param q : c.params()) {
            if (q.log() || q.integer()) {
                throw new ConfigException(source + ": params: " + q.name() + " must be a linear float (no log, no int)");
            }
        }
        order(p.get("t0"), p.get("t1"), source, "the pinch could end before it starts");
        order(p.get("t1"), p.get("t2"), source, "the second motion could start before the pinch ends");
        order(p.get("t2"), p.get("t3"), source, "the second motion could end before it starts");
        if (p.get("t0").low() < 0) {
            throw new ConfigException(source + ": params: t0's low must be >= 0, got " + p.get("t0").low());
        }
        if (p.get("t3").high() > lastEnd) {
            throw new ConfigException(source + ": params: t3's high " + p.get("t3").high() + " is beyond " + lastEnd + " s, the latest "
                    + sleight + " allows");
        }
        for (String speed : List.of("vp", "vs")) {
            if (p.get(speed).low() < 0) {
                throw new ConfigException(source + ": params: " + speed + "'s low must be >= 0, got " + p.get(speed).low());
            }
            if (p.get(speed).high() > MAX_SPEED) {
                throw new ConfigException(source + ": params: " + speed + "'s high must be <= " + MAX_SPEED
                        + " m/s (a flick of the finger), got " + p.get(speed).high());
            }
        }
    }

    private static void order(Param first, Param second, String source, String why) {
        if (second.low() < first.high()) {
            throw new ConfigException(source + ": params: " + second.name() + "'s low " + second.low() + " is below " + first.name()
                    + "'s high " + first.high() + ": " + why);
        }
    }
}
