package handsim.cards.tpe;

/**
 * A finished trial as the sampler sees it: its number, its parameter values (in search-space
 * order, in their own units) and its objective values (one per direction, all finite).
 */
public record CompletedTrial(int number, double[] params, double[] values) {

    public CompletedTrial {
        params = params.clone();
        values = values.clone();
        for (double v : values) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("trial " + number + ": objective values must be finite, got " + v);
            }
        }
    }

    @Override
    public double[] params() {
        return params.clone();
    }

    @Override
    public double[] values() {
        return values.clone();
    }

    double param(int i) {
        return params[i];
    }

    double value(int i) {
        return values[i];
    }
}
