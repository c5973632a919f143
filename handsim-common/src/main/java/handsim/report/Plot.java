package handsim.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A small x-y chart written as PNG with Java2D (no display needed): line, point and bar series,
 * axis ticks, labels and a legend. Enough for apex-per-loop, learning curves and histograms.
 */
public final class Plot {

    /** How a series is drawn. */
    public enum Style { LINE, POINTS, LINE_POINTS, BARS }

    private record Series(String label, double[] x, double[] y, Color color, Style style) {
    }

    public static final Color BLUE = new Color(31, 119, 180);
    public static final Color ORANGE = new Color(255, 127, 14);
    public static final Color GREEN = new Color(44, 160, 44);
    public static final Color RED = new Color(214, 39, 40);
    public static final Color GREY = new Color(127, 127, 127);

    private static final int WIDTH = 900;
    private static final int HEIGHT = 540;
    private static final int LEFT = 80, RIGHT = 30, TOP = 50, BOTTOM = 60;

    private final String title;
    private final String xLabel;
    private final String yLabel;
    private final List<Series> series = new ArrayList<>();
    private double[] yRange;

    public Plot(String title, String xLabel, String yLabel) {
        this.title = title;
        this.xLabel = xLabel;
        this.yLabel = yLabel;
    }

    public Plot add(String label, double[] x, double[] y, Color color, Style style) {
        if (x.length != y.length) {
            throw new IllegalArgumentException("series \"" + label + "\": " + x.length + " x values but " + y.length + " y values");
        }
        series.add(new Series(label, x.clone(), y.clone(), color, style));
        return this;
    }

    /** Fixes the y axis range instead of fitting it to the data. */
    public Plot yRange(double low, double high) {
        yRange = new double[] {low, high};
        return this;
    }

    /** Writes the chart as a PNG (atomically, {@link Outputs}). */
    public void writePng(Path file) throws IOException {
        Outputs.writePng(file, render());
    }

    /** Charts side by side in one PNG (atomically, {@link Outputs}): pairwise projections of one figure. */
    public static void writePngRow(Path file, List<Plot> plots) throws IOException {
        if (plots.isEmpty()) {
            throw new IllegalArgumentException("no charts to write to " + file);
        }
        BufferedImage row = new BufferedImage(WIDTH * plots.size(), HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = row.createGraphics();
        for (int i = 0; i < plots.size(); i++) {
            g.drawImage(plots.get(i).render(), i * WIDTH, 0, null);
        }
        g.dispose();
        Outputs.writePng(file, row);
    }

    BufferedImage render() {
        Axis xa = xAxis(), ya = yAxis();
        double[] xr = {xa.lo(), xa.hi()}, yr = {ya.lo(), ya.hi()};
        BufferedImage img = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, WIDTH, HEIGHT);
        int pw = WIDTH - LEFT - RIGHT, ph = HEIGHT - TOP - BOTTOM;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        FontMetrics fm = g.getFontMetrics();
        // grid and ticks
        for (double t : ticks(xr)) {
            int px = (int) xa.map(t);
            g.setColor(new Color(235, 235, 235));
            g.drawLine(px, TOP, px, TOP + ph);
            g.setColor(Color.DARK_GRAY);
            String s = format(t);
            g.drawString(s, px - fm.stringWidth(s) / 2, TOP + ph + 18);
        }
        for (double t : ticks(yr)) {
            int py = (int) ya.map(t);
            g.setColor(new Color(235, 235, 235));
            g.drawLine(LEFT, py, LEFT + pw, py);
            g.setColor(Color.DARK_GRAY);
            String s = format(t);
            g.drawString(s, LEFT - 8 - fm.stringWidth(s), py + 5);
        }
        g.setColor(Color.BLACK);
        g.drawRect(LEFT, TOP, pw, ph);
        // series
        g.setClip(LEFT, TOP, pw + 1, ph + 1);
        double barWidth = barWidth(xa);
        for (Series s : series) {
            g.setColor(s.color);
            g.setStroke(new BasicStroke(2f));
            for (int i = 0; i < s.x.length; i++) {
                if (!Double.isFinite(s.y[i])) {
                    continue;
                }
                double px = xa.map(s.x[i]), py = ya.map(s.y[i]);
                if (s.style == Style.BARS) {
                    double base = ya.map(Math.max(yr[0], 0));
                    g.fill(new Rectangle2D.Double(px - barWidth / 2, Math.min(py, base), barWidth, Math.abs(base - py)));
                    continue;
                }
                if (s.style != Style.POINTS && i > 0 && Double.isFinite(s.y[i - 1])) {
                    g.draw(new Line2D.Double(xa.map(s.x[i - 1]), ya.map(s.y[i - 1]), px, py));
                }
                if (s.style != Style.LINE) {
                    g.fill(new java.awt.geom.Ellipse2D.Double(px - 3.5, py - 3.5, 7, 7));
                }
            }
        }
        g.setClip(null);
        // labels and legend
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 16));
        g.drawString(title, LEFT, TOP - 18);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        fm = g.getFontMetrics();
        g.drawString(xLabel, LEFT + pw / 2 - fm.stringWidth(xLabel) / 2, HEIGHT - 15);
        var rot = g.getTransform();
        g.rotate(-Math.PI / 2);
        g.drawString(yLabel, -(TOP + ph / 2) - fm.stringWidth(yLabel) / 2, 20);
        g.setTransform(rot);
        // the legend, as wide as its longest label, on a white box in the corner that hides the least data
        int labelWidth = 0;
        for (Series s : series) {
            labelWidth = Math.max(labelWidth, fm.stringWidth(s.label));
        }
        int legendW = labelWidth + 42, legendH = 20 * series.size() + 6;
        java.awt.Rectangle box = legendBox(legendCorner(xa, ya, legendW, legendH), legendW, legendH);
        g.setColor(new Color(255, 255, 255, 220));
        g.fill(box);
        int lx = box.x + 6, ly = box.y + 16;
        for (Series s : series) {
            g.setColor(s.color);
            g.fillRect(lx, ly - 9, 18, 8);
            g.setColor(Color.BLACK);
            g.drawString(s.label, lx + 25, ly);
            ly += 20;
        }
        g.dispose();
        return img;
    }

    /** Where the legend may go, in order of preference. */
    enum Corner { TOP_RIGHT, TOP_LEFT, BOTTOM_RIGHT, BOTTOM_LEFT }

    /**
     * The corner where a legend of w x h pixels covers the fewest data: the points, and the lines
     * between them sampled every 2 pixels. Ties go to the earlier corner of {@link Corner}.
     */
    Corner legendCorner(int w, int h) {
        return legendCorner(xAxis(), yAxis(), w, h);
    }

    private Corner legendCorner(Axis xa, Axis ya, int w, int h) {
        long[] covered = new long[Corner.values().length];
        for (Series s : series) {
            for (int i = 0; i < s.x.length; i++) {
                if (!Double.isFinite(s.y[i])) {
                    continue;
                }
                double px = xa.map(s.x[i]), py = ya.map(s.y[i]);
                boolean line = s.style != Style.POINTS && i > 0 && Double.isFinite(s.y[i - 1]);
                double qx = line ? xa.map(s.x[i - 1]) : px, qy = line ? ya.map(s.y[i - 1]) : py;
                int samples = 1 + (int) (Math.hypot(px - qx, py - qy) / 2);
                for (int k = 0; k < samples; k++) {
                    double t = (double) k / samples, x = px + t * (qx - px), y = py + t * (qy - py);
                    for (Corner c : Corner.values()) {
                        if (legendBox(c, w, h).contains(x, y)) {
                            covered[c.ordinal()]++;
                        }
                    }
                }
            }
        }
        Corner best = Corner.TOP_RIGHT;
        for (Corner c : Corner.values()) {
            if (covered[c.ordinal()] < covered[best.ordinal()]) {
                best = c;
            }
        }
        return best;
    }

    /** The legend's box in a corner of the plot area, 4 pixels in from its frame. */
    private static java.awt.Rectangle legendBox(Corner c, int w, int h) {
        boolean right = c == Corner.TOP_RIGHT || c == Corner.BOTTOM_RIGHT, top = c == Corner.TOP_RIGHT || c == Corner.TOP_LEFT;
        return new java.awt.Rectangle(right ? WIDTH - RIGHT - 4 - w : LEFT + 4, top ? TOP + 4 : HEIGHT - BOTTOM - 4 - h, w, h);
    }

    private double barWidth(Axis xa) {
        double step = Double.POSITIVE_INFINITY;
        for (Series s : series) {
            if (s.style == Style.BARS) {
                for (int i = 1; i < s.x.length; i++) {
                    step = Math.min(step, Math.abs(s.x[i] - s.x[i - 1]));
                }
            }
        }
        return Double.isFinite(step) ? 0.85 * Math.abs(xa.map(step) - xa.map(0)) : 8;
    }

    private double[] range(boolean x) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Series s : series) {
            for (double v : x ? s.x : s.y) {
                if (Double.isFinite(v)) {
                    lo = Math.min(lo, v);
                    hi = Math.max(hi, v);
                }
            }
            if (!x && s.style == Style.BARS) {
                lo = Math.min(lo, 0);
            }
        }
        if (!Double.isFinite(lo)) {
            return new double[] {0, 1};
        }
        double pad = hi > lo ? 0.05 * (hi - lo) : Math.max(1e-3, 0.1 * Math.abs(hi));
        return new double[] {lo - pad, hi + pad};
    }

    /** About six round tick values across the range. */
    static List<Double> ticks(double[] r) {
        double raw = (r[1] - r[0]) / 6, mag = Math.pow(10, Math.floor(Math.log10(raw)));
        double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
        List<Double> out = new ArrayList<>();
        for (double t = Math.ceil(r[0] / step) * step; t <= r[1] + 1e-12; t += step) {
            out.add(Math.abs(t) < step * 1e-9 ? 0 : t);
        }
        return out;
    }

    private static String format(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e6) {
            return Long.toString((long) v);
        }
        return String.format(java.util.Locale.ROOT, Math.abs(v) >= 10 ? "%.1f" : Math.abs(v) >= 1 ? "%.2f" : "%.3f", v)
                .replaceAll("0+$", "").replaceAll("\\.$", "");
    }

    /** The x axis: the data's range across the plot area's width. */
    private Axis xAxis() {
        double[] r = range(true);
        return new Axis(r[0], r[1], LEFT, WIDTH - RIGHT);
    }

    /** The y axis: the fixed or the data's range, up the plot area's height. */
    private Axis yAxis() {
        double[] r = yRange != null ? yRange : range(false);
        return new Axis(r[0], r[1], HEIGHT - BOTTOM, TOP);
    }

    private record Axis(double lo, double hi, double p0, double p1) {
        double map(double v) {
            return p0 + (v - lo) / (hi - lo) * (p1 - p0);
        }
    }
}
