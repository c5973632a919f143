package handsim.cards.sim;

import handsim.cards.mesh.CardMesher;
import org.junit.jupiter.api.Test;

class DropProbe {
    @Test
    void probe() {
        ShellMaterial pes = new ShellMaterial(653, 0.48e6, 0.38, 2.5e-4);
        SoftWorld w = new SoftWorld.Builder()
                .card("card", CardMesher.generate(0.0889, 0.0635, 11, 6, new boolean[4]), pes, SoftWorld.Placement.at(0, 0, 0.002))
                .ground(0).build();
        SolverSettings s = new SolverSettings(0.01, 1e-4, 1e-3, 50, 0.9, 0.4, 1e-3, 1e11, new double[] {0, 0, -9.81}, 0.01);
        Simulator sim = new Simulator(w, s, BoneMotion.STILL);
        SimState st = w.restState();
        for (int i = 0; i < 40; i++) {
            StepStats ss = sim.step(st);
            double zmin = 1, vmax = 0;
            for (int k = 0; k < st.nodeCount(); k++) { zmin = Math.min(zmin, st.x[3*k+2]); vmax = Math.max(vmax, Math.abs(st.v[3*k+2])); }
            System.out.printf("step %d it %d ls %d contacts %d minGap %.3e zmin %.5e vmax %.3e kappa %.3e%n", i, ss.newtonIterations, ss.lineSearchHalvings, ss.maxContacts, ss.minGap, zmin, vmax, st.kappa);
        }
    }
}
