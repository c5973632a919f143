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
 * @param stepper what steps the island of arm, hand and object: handsim's own step or ode4j's quickStep
 */
public record SimConfig(double timeStep, Vec3 gravity, double groundHeight, double contactStiffness, double friction,
        int maxContactsPerPair, double linearDampingPerSecond, double angularDampingPerSecond, int solverIterations,
        double sor, Stepper stepper, Divergence divergence) {

    /**
     * The step of the constrained bodies. Both solve the same rows (joints, stops, contacts with
     * ERP/CFM and friction) by projected SOR in ODE's order; {@code HANDSIM} is handsim's own,
     * allocation-free implementation, {@code ODE4J} ode4j's quickStep, the reference.
     */
    public enum Stepper {
        HANDSIM("handsim"), ODE4J("ode4j");

        private final String label;

        Stepper(String label) {
            this.label = label;
        }

        /** Its name in configs/sim.json and on the command line. */
        public String label() {
            return label;
        }

        /** Every stepper's name, in the order of the enum. */
        public static String[] labels() {
            return java.util.Arrays.stream(values()).map(Stepper::label).toArray(String[]::new);
        }

        /** The stepper named {@code label}; a bad name is refused naming {@code where} it came from (a field, an option). */
        public static Stepper named(String where, String label) {
            for (Stepper s : values()) {
                if (s.label.equals(label)) {
                    return s;
                }
            }
            throw new IllegalArgumentException(where + " must be " + String.join(" or ", labels()) + ", got \"" + label + "\"");
        }
    }

    /**
     * When a step has exploded: the object faster than {@code objectSpeed} (m/s), or an arm body
     * of at least {@code spinCheckedMass} (kg) turning faster than {@code bodySpin} (rad/s).
     */
    public record Divergence(double objectSpeed, double bodySpin, double spinCheckedMass) {

        static Divergence parse(Json j) {
            j.allow("comment");
            Divergence d = new Divergence(j.positive("objectSpeed"), j.positive("bodySpin"), j.number("spinCheckedMass", 0, 100));
            j.requireNoUnknownFields();
            return d;
        }
    }

    /*
     * Sanity limits of a world the hand can work in (SI). Outside them a run diverges or means
     * nothing: a step above 10 ms cannot hold the arm's PD servos (their periods are a few ms)
     * and one below 1 us would take days per simulated minute; gravity from a twentieth of the
     * Earth's to ten times it; contacts from a soft 100 N/m (a 0.1 kg ball sinks 1 cm) to a
     * stiff 1e8 N/m (the paper's is 5e4); the ground below the shoulder (0.95 m high).
     */
    static final double MIN_TIME_STEP = 1e-6, MAX_TIME_STEP = 0.01;
    static final double MIN_GRAVITY = 0.5, MAX_GRAVITY = 100;
    static final double MIN_CONTACT_STIFFNESS = 1e2, MAX_CONTACT_STIFFNESS = 1e8;
    static final double MIN_GROUND = -10, MAX_GROUND = 0.5;

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
        Vec3 gravity = j.vec3("gravity");
        if (!(gravity.norm() >= MIN_GRAVITY && gravity.norm() <= MAX_GRAVITY)) {
            throw j.fieldError("gravity", "its magnitude must be in [" + Json.show(MIN_GRAVITY) + ", " + Json.show(MAX_GRAVITY)
                    + "] m/s^2, got " + Json.show(gravity.norm()) + " m/s^2 " + gravity);
        }
        SimConfig c = new SimConfig(
                j.number("timeStep", MIN_TIME_STEP, MAX_TIME_STEP),
                gravity,
                j.number("groundHeight", MIN_GROUND, MAX_GROUND),
                contact.number("stiffness", MIN_CONTACT_STIFFNESS, MAX_CONTACT_STIFFNESS),
                contact.number("friction", 0, 10),
                contact.integer("maxPerPair", 1, 64),
                damping.number("linearPerSecond", 0, 100),
                damping.number("angularPerSecond", 0, 100),
                solver.integer("iterations", 1, 1000),
                solver.number("sor", 0.1, 2.0),
                Stepper.named("stepper", solver.choice("stepper", Stepper.labels())),
                Divergence.parse(j.get("divergence")));
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
                linearDampingPerSecond, angularDampingPerSecond, iterations, sor, stepper, divergence);
    }

    public SimConfig withStepper(Stepper s) {
        return new SimConfig(timeStep, gravity, groundHeight, contactStiffness, friction, maxContactsPerPair,
                linearDampingPerSecond, angularDampingPerSecond, solverIterations, sor, s, divergence);
    }
}
