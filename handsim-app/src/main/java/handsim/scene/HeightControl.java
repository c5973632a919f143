package handsim.scene;

/**
 * How far a person may move the height goal: each raise or lower moves it by {@code step}
 * metres, and the goal range stays within [{@code min}, {@code max}] metres.
 */
public record HeightControl(double step, double min, double max) {

    public HeightControl {
        if (!(step > 0 && min > 0 && max > min)) {
            throw new IllegalArgumentException("height control needs step > 0 and 0 < min < max, got step " + step
                    + ", [" + min + ", " + max + "]");
        }
    }
}
