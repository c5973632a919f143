package handsim.viewer;

import handsim.math.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * The object's recent path for drawing: positions with their simulated times, the oldest
 * forgotten after {@code seconds}. It starts again when time runs backwards (the scene was reset
 * or switched).
 */
public final class Trail {

    private final double seconds;
    private final List<Double> times = new ArrayList<>();
    private final List<Vec3> positions = new ArrayList<>();

    public Trail(double seconds) {
        if (!(seconds > 0)) {
            throw new IllegalArgumentException("a trail must last > 0 s, got " + seconds);
        }
        this.seconds = seconds;
    }

    /** Adds where the object was at simulated time {@code time} (s). */
    public void add(double time, Vec3 position) {
        int n = times.size();
        if (n > 0 && time < times.get(n - 1)) {
            clear();
        } else if (n > 0 && time == times.get(n - 1)) {
            return;
        }
        times.add(time);
        positions.add(position);
        while (times.size() > 1 && time - times.get(0) > seconds) {
            times.remove(0);
            positions.remove(0);
        }
    }

    public void clear() {
        times.clear();
        positions.clear();
    }

    public int size() {
        return times.size();
    }

    public double time(int i) {
        return times.get(i);
    }

    public Vec3 position(int i) {
        return positions.get(i);
    }

    /** How long a point stays on the trail (s). */
    public double seconds() {
        return seconds;
    }
}
