package handsim.cards.sleight;

import handsim.cards.mesh.CardMesher;
import handsim.cards.mesh.ShellMesh;
import handsim.config.Json;

/**
 * The playing card of a sleight's scene (the {@code card} object of its config): size (m), grid
 * cells along its long and short sides, how many corners are rounded (thesis Fig. 3.6), and the
 * extra gap between stacked cards as a fraction of their thickness (thesis 4.2.2: 5 %).
 */
public record CardSpec(double length, double width, int cellsLong, int cellsShort, int roundedCorners, double gapFraction) {

    /** Reads the fields of {@code card}; the caller checks for unknown fields once it has read its own. */
    /** The most grid cells a card side may have: 200 (0.44 mm cells on a playing card, against the thesis' 11 x 6). */
    static final int MAX_CELLS = 200;

    static CardSpec parse(Json card) {
        card.allow("comment");
        int[] cells = SceneFields.ints(card, "cells", 2);
        if (cells[0] < 2 || cells[1] < 2 || cells[0] > MAX_CELLS || cells[1] > MAX_CELLS) {
            throw card.fieldError("cells", "need 2 to " + MAX_CELLS + " a side, got " + java.util.Arrays.toString(cells));
        }
        return new CardSpec(card.number("length", 1e-3, 1), card.number("width", 1e-3, 1), cells[0], cells[1],
                card.integer("roundedCorners", 0, 4), card.number("gapFraction", 0, 10));
    }

    /** The card's mid-surface, centred at the origin in its xy-plane (x along the long side). */
    public ShellMesh mesh() {
        boolean[] rounded = new boolean[4];
        for (int i = 0; i < roundedCorners; i++) {
            rounded[i] = true;
        }
        return CardMesher.generate(length, width, cellsLong, cellsShort, rounded);
    }
}
