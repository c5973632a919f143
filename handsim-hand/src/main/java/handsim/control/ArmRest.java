package handsim.control;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.model.Dof;
import handsim.model.HandModel;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * The arm posture the IK draws the arm's redundancy toward in some states of the controller. The
 * palm's pose fixes six of the seven DOFs of its chain (shoulder 3, elbow 1, wrist 3); the seventh,
 * the swivel of the elbow about the shoulder-wrist line, follows the path of the IK's solutions
 * (eq. 2 has no term for it). Over a juggler's first loops it drifts from where the catch of the
 * throw-in leaves it to where the loops hold it, and a policy trained on long episodes throws from
 * the latter. Each control tick of the states in {@code phases}, after its IK solve, moves the chain
 * by {@code gain} of its difference to the posture, projected on the null space of the palm's
 * Jacobian ({@link DlsIk#pullNullSpace}): the palm keeps its path (to first order; the next solve
 * corrects the rest), and at the posture the pull is zero.
 *
 * @param jointsDeg the posture (deg), by DOF name: every DOF of the palm's chain
 * @param gain the share of the difference moved per control tick, in (0, 1]
 * @param phases the controller's states in which the arm is drawn (at least one)
 */
public record ArmRest(Map<String, Double> jointsDeg, double gain, Set<Phase> phases) {

    public ArmRest {
        jointsDeg = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(jointsDeg));
        if (phases.isEmpty()) {
            throw new IllegalArgumentException("an arm rest needs at least one state to draw the arm in");
        }
        phases = java.util.Collections.unmodifiableSet(EnumSet.copyOf(phases));
        if (!(gain > 0 && gain <= 1)) {
            throw new IllegalArgumentException("an arm rest's gain must lie in (0, 1], got " + gain);
        }
    }

    /** {@code {jointsDeg: {name: deg, ...}, gain, phases: [state, ...]}}. */
    public static ArmRest parse(Json j) {
        j.allow("comment");
        Json joints = j.get("jointsDeg");
        Map<String, Double> deg = new LinkedHashMap<>();
        for (String name : joints.fieldNames()) {
            deg.put(name, joints.number(name, -360, 360));
        }
        double gain = j.number("gain", 0, 1);
        if (gain == 0) {
            throw j.fieldError("gain", "must be greater than 0 (in (0, 1]), got 0");
        }
        Set<Phase> phases = EnumSet.noneOf(Phase.class);
        for (Json p : j.array("phases")) {
            String name = p.asString();
            try {
                phases.add(Phase.valueOf(name));
            } catch (IllegalArgumentException e) {
                throw j.fieldError("phases", "must name controller states (CATCH, MIDDLE, THROW, GOBACK), got \"" + name + "\"");
            }
        }
        if (phases.isEmpty()) {
            throw j.fieldError("phases", "must name at least one controller state (CATCH, MIDDLE, THROW, GOBACK)");
        }
        ArmRest r = new ArmRest(deg, gain, phases);
        j.requireNoUnknownFields();
        return r;
    }

    public ObjectNode toJson() {
        ObjectNode j = Json.mapper().createObjectNode();
        ObjectNode joints = j.putObject("jointsDeg");
        jointsDeg.forEach(joints::put);
        j.put("gain", gain);
        phases.forEach(p -> j.withArray("phases").add(p.name()));
        return j;
    }

    /**
     * The posture in radians in the order of {@code chainDofs} (model DOF indices). Fails naming the
     * DOF when the posture misses one of the chain, names one outside it, or lies outside a DOF's range.
     */
    public double[] chainVector(HandModel model, int[] chainDofs) {
        Map<String, Integer> chain = new LinkedHashMap<>();
        for (int d : chainDofs) {
            chain.put(model.dofs().get(d).name(), d);
        }
        for (String name : jointsDeg.keySet()) {
            if (!chain.containsKey(name)) {
                throw new IllegalArgumentException("jointsDeg: \"" + name + "\" is not a DOF of the palm's chain ("
                        + String.join(", ", chain.keySet()) + ")");
            }
        }
        double[] q = new double[chainDofs.length];
        int c = 0;
        for (Map.Entry<String, Integer> e : chain.entrySet()) {
            Double deg = jointsDeg.get(e.getKey());
            if (deg == null) {
                throw new IllegalArgumentException("jointsDeg: no angle for " + e.getKey() + " (it needs every DOF of "
                        + String.join(", ", chain.keySet()) + ")");
            }
            Dof dof = model.dofs().get(e.getValue());
            q[c] = Math.toRadians(deg);
            if (q[c] < dof.lower() || q[c] > dof.upper()) {
                throw new IllegalArgumentException("jointsDeg." + e.getKey() + ": " + Json.show(deg) + " deg lies outside the DOF's range ["
                        + showDeg(dof.lower()) + ", " + showDeg(dof.upper()) + "] deg");
            }
            c++;
        }
        return q;
    }

    /** An angle (rad) in degrees as the model file writes it (rounded to 1e-9 deg). */
    private static String showDeg(double rad) {
        return Json.show(Math.rint(Math.toDegrees(rad) * 1e9) / 1e9);
    }
}
