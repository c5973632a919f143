package handsim.viewer;

/**
 * A deforming triangle surface to draw (a card, a fingertip's skin): vertex positions in the
 * viewer's frame (y up, metres), triangles (counter-clockwise from the front), its colour, and
 * whether both sides are lit (thin shells).
 */
public record SurfaceMesh(float[] positions, int[] triangles, float[] rgba, boolean twoSided) {
}
