package handsim.sim;

import handsim.config.Json;
import handsim.math.Vec3;
import java.nio.file.Path;

/**
 * Physics settings from {@code configs/sim.json} (paper sec. 4.1).
 *
 * @param timeStep h in seconds (0.2 ms)
 * @param contactStiffness kp of every contact, N/m (5e4)
 * @param friction Coulomb friction coefficient of hand-object contacts
 * @param maxContactsPerPair contact points generated per colliding geometry pair
 * @param linearDampingPerSecond air resistance rate on linear velocity, 1/s
 * @param angularDampingPerSecond air resistance rate on angular velocity, 1/s
 * @param solverIterations quickStep iterations
 * @param sor quickStep successive over-relaxation factor
 */
public record SimConfig(double timeStep, Vec3 gravity, double groundHeight, double contactStiffness, double friction,
        int maxContactsPerPair, double linearDampingPerSecond, double angularDampingPerSecond, int solverIterations,
        double sor) {

    public static SimConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static SimConfig parse(Json j) {
        j.allow("comment");
        Json contact = j.get("contact");
        contact.allow("comment");
        Json damping = j.get("damping");
        damping.allow("comment");
        Json solver = j.get("solver");
        solver.allow("comment");
        SimConfig c = new SimConfig(
                j.number("timeStep", 1e-6, 0.01),
                j.vec3("gravity"),
                j.number("groundHeight"),
                contact.positive("stiffness"),
                contact.number("friction", 0, 10),
                contact.integer("maxPerPair", 1, 64),
                damping.number("linearPerSecond", 0, 100),
                damping.number("angularPerSecond", 0, 100),
                solver.integer("iterations", 1, 1000),
                solver.number("sor", 0.1, 2.0));
        for (Json node : new Json[] {contact, damping, solver, j}) {
            node.requireNoUnknownFields();
        }
        return c;
    }

    /** Steps per simulated second. */
    public double stepsPerSecond() {
        return 1.0 / timeStep;
    }

    /**
     * Critical contact damping for a pair of masses (kg; 0 for static geometry):
     * {@code kd = 2 sqrt(kp (m1 + m2))} (sec. 4.1).
     */
    public double contactDamping(double m1, double m2) {
        return 2 * Math.sqrt(contactStiffness * (m1 + m2));
    }

    /** ERP = h kp / (h kp + kd) (sec. 4.1). */
    public double contactErp(double m1, double m2) {
        double hk = timeStep * contactStiffness;
        return hk / (hk + contactDamping(m1, m2));
    }

    /** CFM = 1 / (h kp + kd) (sec. 4.1). */
    public double contactCfm(double m1, double m2) {
        return 1.0 / (timeStep * contactStiffness + contactDamping(m1, m2));
    }

    public SimConfig withSolverIterations(int iterations) {
        return new SimConfig(timeStep, gravity, groundHeight, contactStiffness, friction, maxContactsPerPair,
                linearDampingPerSecond, angularDampingPerSecond, iterations, sor);
    }
}
