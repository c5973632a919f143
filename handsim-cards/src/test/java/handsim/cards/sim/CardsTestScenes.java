package handsim.cards.sim;

import handsim.cards.contact.CollisionMesh.FrictionTable;
import handsim.cards.mesh.CardMesher;
import handsim.cards.mesh.FingertipMesher;
import handsim.cards.sim.SoftWorld.Placement;
import java.nio.file.Path;

/** Small scenes for the simulator tests, with the shipped solver settings. */
final class CardsTestScenes {

    static final ShellMaterial PES = new ShellMaterial(653, 4.8e5, 0.38, 2.5e-4);
    static final ShellMaterial CARD_STOCK = new ShellMaterial(1275, 3e9, 0.3, 2.5e-4);
    static final SolidMaterial SKIN = new SolidMaterial(1500, 5e6, 0.4);
    /** card local (x long, y short, z normal) to world (z, x, y): a card hanging in the xz-plane */
    static final double[] HANGING = {0, 1, 0, 0, 0, 1, 1, 0, 0};

    private CardsTestScenes() {
    }

    static SolverSettings settings() {
        return CardsConfig.solver(Path.of("configs/cards/solver.json"));
    }

    static SolverSettings withGravity(SolverSettings s, double gz) {
        return new SolverSettings(s.timeStep(), s.dhat(), s.newtonTolerance(), s.maxNewtonIterations(), s.cgTolerance(), s.cgMaxIterations(), s.ccdRescaling(),
                s.friction(), s.frictionEpsV(), s.kappaScale(), new double[] {0, 0, gz}, s.hashCell(), s.factorisation(), s.parallel(), s.gaussNewtonContacts());
    }

    static SolverSettings withParallel(SolverSettings s, boolean parallel) {
        return new SolverSettings(s.timeStep(), s.dhat(), s.newtonTolerance(), s.maxNewtonIterations(), s.cgTolerance(), s.cgMaxIterations(), s.ccdRescaling(),
                s.friction(), s.frictionEpsV(), s.kappaScale(), s.gravity(), s.hashCell(), s.factorisation(), parallel, s.gaussNewtonContacts());
    }

    /** A flat PES card {@code height} above a ground plane at z = 0. */
    static SoftWorld cardOverGround(ShellMaterial material, double height, FrictionTable friction) {
        return new SoftWorld.Builder().friction(friction)
                .card("card", CardMesher.generate(0.0889, 0.0635, 11, 6, new boolean[4]), material, Placement.at(0, 0, height))
                .ground(0).build();
    }

    /**
     * One card hanging in the xz-plane between two coarse fingertips (7 x 5 x 5 grid, one soft
     * layer) whose skins start {@code gap} off its faces, 14 mm below its top edge.
     */
    static SoftWorld pinchedCard(ShellMaterial card, double gap, FrictionTable friction) {
        double a = 0.012;
        double b = 0.0075;
        double c = 0.006;
        double tipY = card.thickness() / 2 + c + gap;
        double tipZ = 0.0889 / 2 - 0.014;
        var tip = FingertipMesher.generate(a, b, c, 7, 5, 5, 1);
        return new SoftWorld.Builder().friction(friction)
                .card("card", CardMesher.generate(0.0889, 0.0635, 11, 6, new boolean[4]), card, new Placement(HANGING, new double[] {0, 0, 0}))
                .fingertip("thumb", tip, SKIN, new Placement(HANGING, new double[] {0, -tipY, tipZ}))
                .fingertip("finger", tip, SKIN, new Placement(HANGING, new double[] {0, tipY, tipZ}))
                .build();
    }

    /** Mean z of a body's nodes. */
    static double meanZ(SoftWorld w, SimState s, String body) {
        SoftBody b = w.body(body);
        double z = 0;
        for (int i = 0; i < b.nodeCount(); i++) {
            z += s.x[3 * (b.firstNode() + i) + 2];
        }
        return z / b.nodeCount();
    }
}
