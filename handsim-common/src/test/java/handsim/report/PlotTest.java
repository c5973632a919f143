package handsim.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The legend goes where it hides no data, and a chart is written as a PNG. */
@Tag("fast")
class PlotTest {

    private static final int LEGEND_W = 200, LEGEND_H = 46; // two labels

    private static Plot plot(double[] x, double[] y) {
        return new Plot("t", "x", "y").add("a", x, y, Plot.BLUE, Plot.Style.LINE).add("b", x, y, Plot.ORANGE, Plot.Style.LINE);
    }

    @Test
    void theLegendTakesTheFirstCornerFreeOfData() {
        double[] x = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
        // a line rising from the bottom-left corner to the top-right one: the top-left is the first free corner
        assertEquals(Plot.Corner.TOP_LEFT, plot(x, x.clone()).legendCorner(LEGEND_W, LEGEND_H));
        // a line rising from the bottom-left, then along the top: the bottom-right is the first free corner
        double[] top = {0, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10};
        assertEquals(Plot.Corner.BOTTOM_RIGHT, plot(x, top).legendCorner(LEGEND_W, LEGEND_H));
        // a line across the middle (the y axis fixed to 0..10) leaves every corner free: the preferred top-right
        double[] mid = {5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5};
        assertEquals(Plot.Corner.TOP_RIGHT, plot(x, mid).yRange(0, 10).legendCorner(LEGEND_W, LEGEND_H));
    }

    @Test
    void aChartIsWrittenAsAPng(@TempDir Path tmp) throws Exception {
        Path png = tmp.resolve("chart.png");
        double[] x = {1, 2, 3};
        plot(x, new double[] {1, Double.NaN, 3}).writePng(png);
        byte[] head = java.util.Arrays.copyOf(Files.readAllBytes(png), 4);
        assertTrue(head[1] == 'P' && head[2] == 'N' && head[3] == 'G', "a PNG file");
    }
}
