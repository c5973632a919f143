package handsim.task;

import handsim.config.Json;
import handsim.control.NominalThrows;
import handsim.control.ThrowParameters;
import handsim.math.Vec3;
import handsim.sim.Simulator;
import java.util.SplittableRandom;

/**
 * Hit a box and catch the rebound (paper sec. 4.3): a cube fixed above the hand for the whole
 * episode, placed by the episode's seed within a region (or at a given spot, for evaluation and
 * for a person moving it). Reward eq. (6): 1 when the throw hit the box and the object was then
 * caught, otherwise {@code -missWeight d} with d the least object-box distance of the loop.
 */
public final class BoxTask implements ThrowTask {

    /**
     * {@code configs/tasks/box.json}.
     *
     * @param size edge length of the cube (m)
     * @param regionLow, regionHigh corners of the region the box centre is drawn from, relative
     *     to the neutral palm centre (m, world axes)
     * @param missWeight the 0.1 of eq. (6) (1/m)
     * @param apexMargin the nominal throw's apex lies this far above the box's bottom face (m)
     * @param horizontalGain the nominal throw's horizontal palm offset per metre of the box's
     *     horizontal offset from the palm
     * @param loopsRequired hit-and-catch loops in a row that make a box trial a success
     */
    public record Config(double size, Vec3 regionLow, Vec3 regionHigh, double missWeight, double apexMargin,
            double horizontalGain, int loopsRequired) {

        public static Config parse(Json j) {
            j.allow("comment", "loopsRequiredComment");
            Json region = j.get("region");
            double[] x = region.range("x"), y = region.range("y"), z = region.range("z");
            region.requireNoUnknownFields();
            Config c = new Config(j.positive("size"), new Vec3(x[0], y[0], z[0]), new Vec3(x[1], y[1], z[1]),
                    j.number("missWeight", 0, 100), j.number("apexMargin", -1, 1), j.number("horizontalGain", 0, 10),
                    j.integer("loopsRequired", 1, 1000));
            j.requireNoUnknownFields();
            return c;
        }

        /** Centre of the region (relative to the neutral palm centre). */
        public Vec3 regionCenter() {
            return regionLow.plus(regionHigh).times(0.5);
        }
    }

    private final Config config;
    private final NominalThrows nominal;
    private final Vec3 neutralPalm;
    private Vec3 placed;
    private Vec3 box;

    public BoxTask(Config config, NominalThrows nominal, Vec3 neutralPalm) {
        this.config = config;
        this.nominal = nominal;
        this.neutralPalm = neutralPalm;
    }

    public Config config() {
        return config;
    }

    /**
     * Puts the box of every following episode at {@code center} (m, world) instead of drawing it
     * from the region; null draws it again.
     */
    public void placeAt(Vec3 center) {
        placed = center;
    }

    /** The box centre a seed draws from the region (m, world). */
    public Vec3 drawCenter(long seed) {
        SplittableRandom rng = new SplittableRandom(seed ^ 0x5DEECE66DL);
        Vec3 lo = config.regionLow(), hi = config.regionHigh();
        return neutralPalm.plus(new Vec3(lo.x() + rng.nextDouble() * (hi.x() - lo.x()),
                lo.y() + rng.nextDouble() * (hi.y() - lo.y()), lo.z() + rng.nextDouble() * (hi.z() - lo.z())));
    }

    /** The centre of the box region (m, world). */
    public Vec3 regionCenter() {
        return neutralPalm.plus(config.regionCenter());
    }

    /** The largest distance a box centre can have from the region's centre: half the region's diagonal (m). */
    public double regionRadius() {
        return 0.5 * config.regionHigh().distance(config.regionLow());
    }

    /** Distance (m) of a box centre from the centre of the region. */
    public double distanceFromRegionCenter(Vec3 center) {
        return center.distance(neutralPalm.plus(config.regionCenter()));
    }

    /** The box to draw (m, world): this episode's, else the one placed for the next, else the region's centre. */
    public Vec3 shownBox() {
        return box != null ? box : placed != null ? placed : regionCenter();
    }

    /** Where the next episode's box stands (m, world): where it was placed, else this episode's, else the region's centre. */
    public Vec3 nextBox() {
        return placed != null ? placed : box != null ? box : regionCenter();
    }

    /** The box of the current episode (m, world). */
    public Vec3 box() {
        return box;
    }

    @Override
    public String name() {
        return "box";
    }

    @Override
    public int goalSize() {
        return 3;
    }

    @Override
    public void start(Simulator sim, long seed) {
        box = placed != null ? placed : drawCenter(seed);
        double s = config.size();
        sim.addStaticBox(box, new Vec3(s, s, s));
    }

    @Override
    public double[] goal() {
        return new double[] {box.x(), box.y(), box.z()};
    }

    @Override
    public void advance() {
        // the box stays where it is for the whole episode
    }

    /**
     * Up to just above the box's bottom face, leaning toward it: the height table's throw for
     * that apex, with a horizontal palm offset proportional to the box's horizontal offset.
     */
    @Override
    public ThrowParameters nominalThrow() {
        ThrowParameters up = nominal.forHeight(box.y() - 0.5 * config.size() + config.apexMargin());
        Vec3 lean = box.minus(neutralPalm).times(config.horizontalGain());
        return new ThrowParameters(new Vec3(lean.x(), up.dOffset().y(), lean.z()), up.rTarget(), up.tOpen());
    }

    /** eq. (6). */
    @Override
    public double reward(LoopRecord loop) {
        return success(loop) ? 1 : -config.missWeight() * loop.boxDistance();
    }

    @Override
    public boolean success(LoopRecord loop) {
        return loop.boxHit() && loop.caught();
    }


}
