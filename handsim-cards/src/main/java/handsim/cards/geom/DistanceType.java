package handsim.cards.geom;

import handsim.cards.geom.Distances.Kernel;

/**
 * Which features of two primitives are closest (the IPC Toolkit's distance types), and so which
 * smooth kernel gives their distance and on which vertices of the stencil it acts. Stencils are
 * point–triangle [p, t0, t1, t2], edge–edge [ea0, ea1, eb0, eb1] and point–edge [p, e0, e1].
 */
public enum DistanceType {
    PT_P_T0("P_T0", Kernel.POINT_POINT, 0, 1),
    PT_P_T1("P_T1", Kernel.POINT_POINT, 0, 2),
    PT_P_T2("P_T2", Kernel.POINT_POINT, 0, 3),
    PT_P_E0("P_E0", Kernel.POINT_LINE, 0, 1, 2),
    PT_P_E1("P_E1", Kernel.POINT_LINE, 0, 2, 3),
    PT_P_E2("P_E2", Kernel.POINT_LINE, 0, 3, 1),
    PT_P_T("P_T", Kernel.POINT_PLANE, 0, 1, 2, 3),
    EE_EA0_EB0("EA0_EB0", Kernel.POINT_POINT, 0, 2),
    EE_EA0_EB1("EA0_EB1", Kernel.POINT_POINT, 0, 3),
    EE_EA1_EB0("EA1_EB0", Kernel.POINT_POINT, 1, 2),
    EE_EA1_EB1("EA1_EB1", Kernel.POINT_POINT, 1, 3),
    EE_EA_EB0("EA_EB0", Kernel.POINT_LINE, 2, 0, 1),
    EE_EA_EB1("EA_EB1", Kernel.POINT_LINE, 3, 0, 1),
    EE_EA0_EB("EA0_EB", Kernel.POINT_LINE, 0, 2, 3),
    EE_EA1_EB("EA1_EB", Kernel.POINT_LINE, 1, 2, 3),
    EE_EA_EB("EA_EB", Kernel.LINE_LINE, 0, 1, 2, 3),
    PE_P_E0("P_E0", Kernel.POINT_POINT, 0, 1),
    PE_P_E1("P_E1", Kernel.POINT_POINT, 0, 2),
    PE_P_E("P_E", Kernel.POINT_LINE, 0, 1, 2);

    private final String ipcName;
    private final Kernel kernel;
    private final int[] vertices;

    DistanceType(String ipcName, Kernel kernel, int... vertices) {
        this.ipcName = ipcName;
        this.kernel = kernel;
        this.vertices = vertices;
    }

    /** The IPC Toolkit's name of this type, e.g. {@code P_E1} or {@code EA0_EB}. */
    public String ipcName() {
        return ipcName;
    }

    public Kernel kernel() {
        return kernel;
    }

    /** Stencil positions of the kernel's vertices, in the kernel's order. */
    public int[] vertices() {
        return vertices.clone();
    }

    /** Stencil position of the kernel's {@code i}-th vertex. */
    public int vertex(int i) {
        return vertices[i];
    }

    public int vertexCount() {
        return vertices.length;
    }

    /** The same closest-feature type with edge A's end points given in the other order. */
    public DistanceType withEdgeAReversed() {
        return switch (this) {
            case EE_EA0_EB0 -> DistanceType.EE_EA1_EB0;
            case EE_EA0_EB1 -> DistanceType.EE_EA1_EB1;
            case EE_EA1_EB0 -> DistanceType.EE_EA0_EB0;
            case EE_EA1_EB1 -> DistanceType.EE_EA0_EB1;
            case EE_EA0_EB -> DistanceType.EE_EA1_EB;
            case EE_EA1_EB -> DistanceType.EE_EA0_EB;
            default -> this;
        };
    }

    /** The same closest-feature type with edge B's end points given in the other order. */
    public DistanceType withEdgeBReversed() {
        return switch (this) {
            case EE_EA0_EB0 -> DistanceType.EE_EA0_EB1;
            case EE_EA0_EB1 -> DistanceType.EE_EA0_EB0;
            case EE_EA1_EB0 -> DistanceType.EE_EA1_EB1;
            case EE_EA1_EB1 -> DistanceType.EE_EA1_EB0;
            case EE_EA_EB0 -> DistanceType.EE_EA_EB1;
            case EE_EA_EB1 -> DistanceType.EE_EA_EB0;
            default -> this;
        };
    }

    /** The same closest-feature type with edges A and B given in the other order. */
    public DistanceType withEdgesSwapped() {
        return switch (this) {
            case EE_EA0_EB1 -> DistanceType.EE_EA1_EB0;
            case EE_EA1_EB0 -> DistanceType.EE_EA0_EB1;
            case EE_EA_EB0 -> DistanceType.EE_EA0_EB;
            case EE_EA_EB1 -> DistanceType.EE_EA1_EB;
            case EE_EA0_EB -> DistanceType.EE_EA_EB0;
            case EE_EA1_EB -> DistanceType.EE_EA_EB1;
            default -> this;
        };
    }
}
