package handsim.app;

import picocli.CommandLine.Option;

/** The options of the card commands: the fingertip mesh, the card preset and the frames. */
final class CardsSceneOptions {

    @Option(names = "--mesh", paramLabel = "NAME", description = "fingertip resolution: thesis, reduced or coarse (default: the sleight config's)")
    String mesh;

    @Option(names = "--card", paramLabel = "PRESET", description = "card material preset of configs/cards/materials.json (default: the file's)")
    String card;

    @Option(names = "--width", defaultValue = "640", description = "frame width in pixels (default: ${DEFAULT-VALUE})")
    int width;

    @Option(names = "--height", defaultValue = "480", description = "frame height in pixels (default: ${DEFAULT-VALUE})")
    int height;

    @Option(names = "--no-frames", description = "render no PNG frames (no display needed)")
    boolean noFrames;

    /** Frame sizes of 16 to 8192 pixels; others are refused by option name. */
    void checkFrameSize() {
        if (width < 16 || width > 8192) {
            throw new IllegalArgumentException("--width must be in [16, 8192], got " + width);
        }
        if (height < 16 || height > 8192) {
            throw new IllegalArgumentException("--height must be in [16, 8192], got " + height);
        }
    }

    /** The frame width to render, 0 for none. */
    int frameWidth() {
        return noFrames ? 0 : width;
    }
}
