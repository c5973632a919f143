package handsim.model;

/**
 * How a joint rotates. Every joint is a chain of 1-3 rotations about axes given in the parent
 * frame of the zero configuration, applied intrinsically: R = R(a0, q0) R(a1, q1) R(a2, q2).
 * The first axis stays fixed in the parent, the last one in the child.
 */
public enum JointType {
    /** One axis. */
    HINGE(1),
    /** Two perpendicular axes (a Cardan joint): first fixed in the parent, second in the child. */
    UNIVERSAL(2),
    /** Three mutually perpendicular axes (Euler angles); the middle angle must stay inside (-90, 90) degrees. */
    BALL(3);

    private final int dofCount;

    JointType(int dofCount) {
        this.dofCount = dofCount;
    }

    public int dofCount() {
        return dofCount;
    }

    public static JointType parse(String s) {
        return switch (s) {
            case "hinge" -> HINGE;
            case "universal" -> UNIVERSAL;
            case "ball" -> BALL;
            default -> throw new IllegalArgumentException(s);
        };
    }
}
