package handsim.sim;

/** The simulation produced a non-finite or exploding state; the episode must end, not be silently reset. */
public class SimulationDiverged extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public SimulationDiverged(String message) {
        super(message);
    }
}
