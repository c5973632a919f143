package handsim.report;

import java.util.Locale;

/** Wall times in progress lines, as people read them: 42s, 3m05s, 1h02m. */
public final class Durations {

    private Durations() {
    }

    /** {@code seconds} rounded to the second below an hour, to the minute above. */
    public static String clock(double seconds) {
        long s = Math.round(seconds);
        if (s < 60) {
            return s + "s";
        }
        if (s < 3600) {
            return String.format(Locale.ROOT, "%dm%02ds", s / 60, s % 60);
        }
        return String.format(Locale.ROOT, "%dh%02dm", s / 3600, (s % 3600) / 60);
    }
}
