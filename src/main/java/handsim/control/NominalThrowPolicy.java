package handsim.control;

import java.util.function.DoubleSupplier;

/** The hand-tuned throw for the currently desired apex height (sec. 4.2: tuned per height). */
public final class NominalThrowPolicy implements ThrowPolicy {

    private final NominalThrows table;
    private final DoubleSupplier desiredHeight;

    public NominalThrowPolicy(NominalThrows table, DoubleSupplier desiredHeight) {
        this.table = table;
        this.desiredHeight = desiredHeight;
    }

    @Override
    public ThrowParameters decide(Observation observation) {
        return table.forHeight(desiredHeight.getAsDouble());
    }
}
