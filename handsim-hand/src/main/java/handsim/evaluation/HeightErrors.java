package handsim.evaluation;

import handsim.task.LoopRecord;

import handsim.report.Plot;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * The height task's accuracy over a set of throws (paper sec. 4.2, Fig. 5): the signed error
 * apex - target of every throw made, its mean, mean magnitude, 95th percentile of the
 * magnitude and the share within 0.1 m.
 *
 * @param errors apex - target of each throw (m), in the order made
 */
public record HeightErrors(double[] errors) {

    public HeightErrors {
        errors = errors.clone();
    }

    /** The errors of every throw (loop index >= 1) of the given loops. */
    public static HeightErrors of(List<LoopRecord> loops) {
        return new HeightErrors(loops.stream().filter(l -> l.index() > 0 && !Double.isNaN(l.targetHeight()))
                .mapToDouble(l -> l.apexHeight() - l.targetHeight()).toArray());
    }

    public int count() {
        return errors.length;
    }

    public double mean() {
        return Arrays.stream(errors).average().orElse(Double.NaN);
    }

    public double absMean() {
        return Arrays.stream(errors).map(Math::abs).average().orElse(Double.NaN);
    }

    /** The 95th percentile of |error| (nearest rank). */
    public double absP95() {
        if (errors.length == 0) {
            return Double.NaN;
        }
        double[] a = Arrays.stream(errors).map(Math::abs).sorted().toArray();
        return a[(int) Math.ceil(0.95 * a.length) - 1];
    }

    /** Share of throws with |error| <= {@code tolerance}. */
    public double within(double tolerance) {
        return errors.length == 0 ? Double.NaN : Arrays.stream(errors).filter(e -> Math.abs(e) <= tolerance).count() / (double) errors.length;
    }

    /** The error histogram (paper Fig. 5): counts per {@code binWidth} bin. */
    public void writeHistogram(Path png, String title, double binWidth) throws IOException {
        double lo = Math.floor(Arrays.stream(errors).min().orElse(-binWidth) / binWidth) * binWidth;
        double hi = Math.ceil(Arrays.stream(errors).max().orElse(binWidth) / binWidth) * binWidth;
        int bins = Math.max(1, (int) Math.round((hi - lo) / binWidth));
        double[] centers = new double[bins], counts = new double[bins];
        for (int b = 0; b < bins; b++) {
            centers[b] = lo + (b + 0.5) * binWidth;
        }
        for (double e : errors) {
            counts[Math.min(bins - 1, (int) Math.floor((e - lo) / binWidth))]++;
        }
        new Plot(title, "apex height - target height (m)", "throws")
                .add(String.format(java.util.Locale.ROOT, "%d throws, mean %+.3f m", errors.length, mean()), centers, counts,
                        Plot.BLUE, Plot.Style.BARS)
                .writePng(png);
    }
}
