package handsim.model;

import handsim.math.Quat;
import handsim.math.Vec3;

/**
 * A named frame fixed on a body: {@code position} in the body frame and {@code orientation}
 * relative to the body frame. The palm centre is the site the controller steers.
 */
public record Site(String name, int body, Vec3 position, Quat orientation) {
}
