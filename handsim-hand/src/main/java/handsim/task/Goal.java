package handsim.task;

import handsim.math.Vec3;

/**
 * What a task asks of the throw, described for drawing: the viewer shows a {@link Height} as a
 * translucent plane and a {@link Box} as a box. World coordinates, metres.
 */
public sealed interface Goal {

    /** The apex height the throw aims at, drawn as a horizontal plane centred above {@code center}. */
    record Height(double height, Vec3 center) implements Goal {
    }

    /** A box to hit (centre, full edge lengths). */
    record Box(Vec3 center, Vec3 size) implements Goal {
    }

    /** A task with nothing to draw. */
    record None() implements Goal {
    }
}
