package handsim.mesh;

import handsim.model.Body;

/**
 * Which of the viewer's colours ({@code configs/viewer.json} colours) a body of the arm and hand
 * wears: the palm's collision shapes (plate, pads, heel) in their own tone, the rest skin.
 */
public enum Surface {
    SKIN,
    PALM;

    private static final String PALM_BODY = "palm";

    public static Surface of(Body body) {
        return body.name().equals(PALM_BODY) ? PALM : SKIN;
    }
}
