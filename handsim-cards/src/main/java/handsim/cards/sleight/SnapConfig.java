package handsim.cards.sleight;

import handsim.config.Json;
import java.nio.file.Path;

/** The Card Snapping scene from configs/cards/snap.json, validated field by field. */
public record SnapConfig(CardSpec card, FingertipSpec fingertip, double pinchBelowTop, double initialGap, double holdDepth,
                         double warmup, double duration, double alphaTargetDegrees, double dropLimit, double droppedObjective,
                         int frameEvery, Slide slide, SnapParams defaults) {

    /**
     * How the slide window moves the bones: STRAIGHT along the cards' short side, in opposite
     * directions (thesis 4.2.4), or TURN about the cards' normal, in opposite senses.
     */
    public enum Slide { STRAIGHT, TURN }

    public static SnapConfig load(Path file) {
        return parse(Json.load(file), null);
    }

    /** @param mesh a fingertip resolution overriding the file's ("thesis", "reduced"), or null */
    public static SnapConfig load(Path file, String mesh) {
        return parse(Json.load(file), mesh);
    }

    public static SnapConfig parse(Json j, String meshOverride) {
        j.allow("comment");
        Json card = j.get("card");
        CardSpec cardSpec = CardSpec.parse(card);
        Json tip = j.get("fingertip");
        FingertipSpec tipSpec = FingertipSpec.parse(tip, meshOverride);
        double pinchBelowTop = tip.number("pinchBelowTop", 0, 1);
        Json hold = j.get("hold");
        hold.allow("comment");
        Json trial = j.get("trial");
        trial.allow("comment");
        double duration = trial.number("duration", 0.01, 100);
        SnapParams defaults = SnapParams.parse(j.get("params"));
        defaults.validate(duration, j.source() + ": params");
        SnapConfig c = new SnapConfig(cardSpec, tipSpec, pinchBelowTop,
                hold.number("initialGap", 0, 0.01), hold.number("depth", 0, 0.01), hold.number("warmup", 0, 10),
                duration, trial.number("alphaTarget", 0, 180), trial.number("dropLimit", 0, 10), trial.number("droppedObjective", 0, 1e6),
                trial.integer("frameEvery", 1, 10_000),
                trial.has("slide") ? Slide.valueOf(trial.choice("slide", "straight", "turn").toUpperCase(java.util.Locale.ROOT)) : Slide.STRAIGHT,
                defaults);
        if (pinchBelowTop > cardSpec.length()) {
            throw tip.fieldError("pinchBelowTop", "must be within the card's length " + Json.show(cardSpec.length()) + " m, got "
                    + Json.show(pinchBelowTop));
        }
        for (Json node : new Json[] {card, tip, hold, trial, j}) {
            node.requireNoUnknownFields();
        }
        return c;
    }

    /** The fingertip resolution's name. */
    public String meshName() {
        return fingertip.meshName();
    }
}
