package handsim.viewer;

import handsim.scene.InteractiveScene;
import handsim.scene.LiveFrame;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The heads-up display: a status panel (the scene's figures, then speed, real-time factor,
 * frame rate, recording) at the top left, recent notes (what a command did, what was
 * substituted) at the top right, and a one-line hint or, with help on, the key list at the
 * bottom. Panels are painted with Java2D and shown as {@link Overlay2D}s; the status panel is
 * repainted at most every {@code refreshSeconds} wall seconds.
 */
final class Hud implements AutoCloseable {

    static final int MARGIN = 12, PADDING = 9, COLUMN_GAP = 14, MAX_NOTES = 4;
    /** Wall seconds between repaints of the status panel (its figures change every frame). */
    static final double REFRESH_SECONDS = 0.1;
    static final String HINT = "H: keys and mouse";
    /** The status and note panels wrap their text to this fraction of the window's width. */
    static final double MAX_PANEL_FRACTION = 0.42;

    /** A label and its value; warnings are drawn in the warning colour. */
    record Row(String label, String value, boolean warning) {
    }

    private record Note(String text, double shownAt) {
    }

    private final ViewerConfig.Palette colours;
    private final Font font;
    private final double noteSeconds;
    private final Deque<Note> notes = new ArrayDeque<>();
    private final Overlay2D status = new Overlay2D();
    private final Overlay2D notePanel = new Overlay2D();
    private final Overlay2D help = new Overlay2D();
    private final Overlay2D hint = new Overlay2D();
    private double statusPaintedAt = Double.NEGATIVE_INFINITY;
    private boolean notesChanged = true;
    private int paintedForWidth;

    Hud(ViewerConfig config) {
        this.colours = config.colours();
        this.font = new Font(Font.SANS_SERIF, Font.PLAIN, config.hud().fontSizePixels());
        this.noteSeconds = config.hud().noteSeconds();
        List<Row> keys = new ArrayList<>();
        for (ViewerAction a : ViewerAction.values()) {
            keys.add(new Row(a.label, a.description, false));
        }
        keys.add(new Row("mouse", "left drag: orbit · right drag: pan · wheel: zoom", false));
        help.set(paint(keys, Integer.MAX_VALUE));
        hint.set(paint(List.of(new Row(HINT, "", false)), Integer.MAX_VALUE));
    }

    /** Shows {@code note} for a while (wall time {@code now}, s). */
    void addNote(String note, double now) {
        notes.addLast(new Note(note, now));
        while (notes.size() > MAX_NOTES) {
            notes.removeFirst();
        }
        notesChanged = true;
    }

    /**
     * The status panel's rows: the scene's figures (its {@link InteractiveScene#FALLBACK} entry as
     * a warning), then the viewer's own.
     */
    static List<Row> rows(LiveFrame frame, double fps, String recording) {
        List<Row> rows = new ArrayList<>();
        for (Map.Entry<String, String> e : frame.status().entrySet()) {
            rows.add(new Row(e.getKey(), e.getValue(), e.getKey().equals(InteractiveScene.FALLBACK)));
        }
        rows.add(new Row("speed", frame.paused() ? "paused" : speed(frame.speed()), frame.paused()));
        rows.add(new Row("real time", Double.isNaN(frame.realTimeFactor()) ? "-"
                : String.format(Locale.ROOT, "%.2f ×", frame.realTimeFactor()), false));
        rows.add(new Row("FPS", Double.isNaN(fps) ? "-" : String.format(Locale.ROOT, "%.0f", fps), false));
        if (recording != null) {
            rows.add(new Row("recording", recording, true));
        }
        return rows;
    }

    /** 1 -> "1 ×", 0.25 -> "1/4 ×", 0.3 -> "0.3 ×". */
    static String speed(double s) {
        if (Math.abs(s - Math.rint(s)) < 1e-9) {
            return Math.round(s) + " ×";
        }
        if (s < 1 && Math.abs(1 / s - Math.rint(1 / s)) < 1e-6) {
            return "1/" + Math.round(1 / s) + " ×";
        }
        return new BigDecimal(s).round(new MathContext(3)).stripTrailingZeros().toPlainString() + " ×";
    }

    /**
     * Draws the panels over a {@code width} x {@code height} framebuffer at wall time {@code now};
     * {@code rows} is asked for only when the status panel is due for a repaint.
     */
    void draw(int width, int height, Supplier<List<Row>> rows, boolean showHelp, double now) {
        int maxWidth = (int) (MAX_PANEL_FRACTION * width);
        if (now - statusPaintedAt >= REFRESH_SECONDS || now < statusPaintedAt || width != paintedForWidth) {
            status.set(paint(rows.get(), maxWidth));
            statusPaintedAt = now;
        }
        if (notes.removeIf(n -> now - n.shownAt() > noteSeconds) || notesChanged || width != paintedForWidth) {
            List<Row> lines = new ArrayList<>();
            for (Note n : notes) {
                lines.add(new Row(n.text(), "", true));
            }
            notePanel.set(paint(lines, maxWidth));
            notesChanged = false;
        }
        paintedForWidth = width;
        Overlay2D.begin(width, height);
        status.draw(MARGIN, MARGIN);
        if (!notes.isEmpty()) {
            notePanel.draw(width - MARGIN - notePanel.width(), MARGIN);
        }
        Overlay2D bottom = showHelp ? help : hint;
        bottom.draw(showHelp ? width - MARGIN - bottom.width() : MARGIN, height - MARGIN - bottom.height());
        Overlay2D.end();
    }

    /**
     * A panel of two columns (labels, values) on the translucent panel colour, at most
     * {@code maxWidth} pixels wide: longer values wrap onto more lines. A row with an empty
     * value spans both columns; warnings are drawn in the warning colour.
     */
    BufferedImage paint(List<Row> rows, int maxWidth) {
        BufferedImage probe = new BufferedImage(1, 1, BufferedImage.TYPE_INT_ARGB);
        Graphics2D pg = probe.createGraphics();
        pg.setFont(font);
        FontMetrics fm = pg.getFontMetrics();
        pg.dispose();
        int labelWidth = 0;
        for (Row r : rows) {
            if (!r.value().isEmpty()) {
                labelWidth = Math.max(labelWidth, fm.stringWidth(r.label()));
            }
        }
        int inner = Math.max(labelWidth + COLUMN_GAP + 4 * fm.charWidth('m'), maxWidth - 2 * PADDING);
        List<String[]> lines = new ArrayList<>();
        List<Boolean> warnings = new ArrayList<>();
        int used = 0;
        for (Row r : rows) {
            boolean span = r.value().isEmpty();
            List<String> parts = wrap(span ? r.label() : r.value(), fm, span ? inner : inner - labelWidth - COLUMN_GAP);
            for (int i = 0; i < parts.size(); i++) {
                lines.add(span ? new String[] {parts.get(i), null} : new String[] {i == 0 ? r.label() : "", parts.get(i)});
                warnings.add(r.warning());
                used = Math.max(used, span ? fm.stringWidth(parts.get(i)) : labelWidth + COLUMN_GAP + fm.stringWidth(parts.get(i)));
            }
        }
        int line = fm.getHeight();
        int w = 2 * PADDING + used, h = 2 * PADDING + Math.max(1, lines.size()) * line;
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(color(colours.hudPanel()));
        g.fillRoundRect(0, 0, w, h, 2 * PADDING, 2 * PADDING);
        g.setFont(font);
        int y = PADDING + fm.getAscent();
        for (int i = 0; i < lines.size(); i++) {
            String[] l = lines.get(i);
            Color text = color(warnings.get(i) ? colours.hudWarning() : colours.hudText());
            if (l[1] == null) {
                g.setColor(text);
                g.drawString(l[0], PADDING, y);
            } else {
                g.setColor(color(colours.hudLabel()));
                g.drawString(l[0], PADDING, y);
                g.setColor(text);
                g.drawString(l[1], PADDING + labelWidth + COLUMN_GAP, y);
            }
            y += line;
        }
        g.dispose();
        return img;
    }

    /** {@code text} broken at spaces into lines of at most {@code width} pixels (a longer word stays whole). */
    static List<String> wrap(String text, FontMetrics fm, int width) {
        List<String> out = new ArrayList<>();
        StringBuilder line = new StringBuilder();
        for (String word : text.split(" ")) {
            if (line.length() > 0 && fm.stringWidth(line + " " + word) > width) {
                out.add(line.toString());
                line.setLength(0);
            }
            line.append(line.length() > 0 ? " " : "").append(word);
        }
        out.add(line.toString());
        return out;
    }

    private static Color color(float[] rgba) {
        return new Color(rgba[0], rgba[1], rgba[2], rgba[3]);
    }

    @Override
    public void close() {
        status.close();
        notePanel.close();
        help.close();
        hint.close();
    }
}
