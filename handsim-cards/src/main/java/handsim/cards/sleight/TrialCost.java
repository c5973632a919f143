package handsim.cards.sleight;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftSimulator;
import handsim.cards.sim.StepStats;
import handsim.cards.study.Evaluation;

/**
 * What a trial cost and how close its surfaces came: the smallest gap d − ξ over every step (m;
 * positive means no interpenetration), steps, Newton iterations, simulated time (s), and the
 * wall time (s) split into assembly (energies, gradients, Hessians), contact (broad and narrow
 * phase, CCD) and solve (factorisation, CG, substitution), with the most active contacts at a
 * step's end. Where a slow trial's time goes: the most Newton iterations one step took (the
 * solver's maxNewtonIterations bounds it), the steps that reached that bound unconverged, and the
 * line search's halvings.
 */
public record TrialCost(double minGap, long steps, long newtonIterations, double simulatedSeconds, double wallSeconds,
                        double assemblySeconds, double contactSeconds, double solveSeconds, int maxContacts,
                        long mostNewtonIterationsInAStep, long unconvergedSteps, long lineSearchHalvings) {

    /** Receives the state after every step of a trial (for recording frames). */
    public interface StepListener {
        void afterStep(SimState state, StepStats step);
    }

    /** Advances {@code state} by {@code steps} steps of {@code sim}, telling {@code listener} (may be null) after each. */
    static TrialCost simulate(SoftSimulator sim, SimState state, int steps, double timeStep, StepListener listener) {
        long start = System.nanoTime();
        double minGap = Double.POSITIVE_INFINITY;
        long most = 0;
        for (int i = 0; i < steps; i++) {
            StepStats st = sim.step(state);
            minGap = Math.min(minGap, st.minGap);
            most = Math.max(most, st.newtonIterations);
            if (listener != null) {
                listener.afterStep(state, st);
            }
        }
        double wall = (System.nanoTime() - start) * 1e-9;
        StepStats total = sim.stats();
        return new TrialCost(minGap, total.steps, total.newtonIterations, steps * timeStep, wall, total.assemblyNanos * 1e-9,
                total.contactNanos * 1e-9, total.solveNanos * 1e-9, total.maxContacts, most, total.unconvergedSteps,
                total.lineSearchHalvings);
    }

    /** Wall time per Newton iteration (s). */
    public double secondsPerIteration() {
        return newtonIterations == 0 ? 0 : wallSeconds / newtonIterations;
    }

    /** {@code e} with these figures kept for a study's record. */
    Evaluation addTo(Evaluation e) {
        return e.with("minGap", minGap)
                .with("newtonIterations", newtonIterations)
                .with("maxContacts", maxContacts)
                .with("mostNewtonIterationsInAStep", mostNewtonIterationsInAStep)
                .with("unconvergedSteps", unconvergedSteps)
                .with("lineSearchHalvings", lineSearchHalvings)
                .with("wallSeconds", wallSeconds)
                .with("assemblySeconds", assemblySeconds)
                .with("contactSeconds", contactSeconds)
                .with("solveSeconds", solveSeconds);
    }

    /** Writes the figures into {@code o} (result.json). */
    public void putInto(ObjectNode o) {
        o.put("minGap", minGap);
        o.put("steps", steps);
        o.put("newtonIterations", newtonIterations);
        o.put("maxContacts", maxContacts);
        o.put("mostNewtonIterationsInAStep", mostNewtonIterationsInAStep);
        o.put("unconvergedSteps", unconvergedSteps);
        o.put("lineSearchHalvings", lineSearchHalvings);
        o.put("wallSeconds", wallSeconds);
        o.put("secondsPerNewtonIteration", secondsPerIteration());
        o.put("assemblySeconds", assemblySeconds);
        o.put("contactSeconds", contactSeconds);
        o.put("solveSeconds", solveSeconds);
    }
}
