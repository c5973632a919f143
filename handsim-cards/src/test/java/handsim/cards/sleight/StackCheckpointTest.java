package handsim.cards.sleight;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.cards.contact.ContactSet;
import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftWorld;
import handsim.config.ConfigException;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The rested stack of Double Lift (thesis 4.2.2): a few cards stacked at their thickness plus 5 %
 * settle on the table without any surface ever touching, their checkpoint restores them bit for
 * bit, and a checkpoint made for other configs is refused.
 */
@Tag("fast")
class StackCheckpointTest {

    /** Three PES cards of 7 x 4 cells on the table (the warm-up has no fingertips; coarse ones keep the trial world small). */
    static LiftTrial fewCards(Path checkpoints, Map<String, String> more) {
        Map<String, String> o = new LinkedHashMap<>(Map.of("double-lift.stack.count", "3", "double-lift.fingertip.mesh", "\"coarse\"",
                "double-lift.fingertip.softLayers", "1", "double-lift.card.cells", "[7, 4]"));
        o.putAll(more);
        List<String> lines = new ArrayList<>();
        return LiftTrial.fromConfigs(Path.of("."), null, "pes", o, checkpoints).withLog(lines::add);
    }

    @Test
    void aFewCardsSettleToRestWithoutTouchingAndTheirCheckpointRestoresBitForBit(@TempDir Path dir) throws Exception {
        LiftTrial trial = fewCards(dir, Map.of());
        SimState rested = trial.restedStack();
        assertTrue(Files.isRegularFile(trial.checkpointFile()), "the warm-up wrote its checkpoint");
        LiftConfig c = trial.scene().config();
        // at rest: no node faster than the rest speed (the warm-up's own criterion, 0.1 mm/s)
        for (double v : rested.v) {
            assertTrue(Math.abs(v) <= c.restSpeed(), "a node still moves at " + v + " m/s");
        }
        // nothing touches: every pair within the barrier's reach keeps a positive gap d − ξ
        SoftWorld stack = trial.scene().stackWorld();
        var solver = CardsConfig.solver(Path.of("configs/cards/solver.json"));
        ContactSet contacts = new ContactSet(stack.collision(), solver.dhat(), solver.hashCell());
        contacts.build(rested.x);
        assertTrue(contacts.size() > 0, "the settled cards rest on each other and on the table");
        assertTrue(contacts.minGap(rested.x) > 0, "smallest gap " + contacts.minGap(rested.x) + " m");
        // they settled by less than the gaps they were stacked with (3 gaps of 5 % of 0.25 mm), and not upwards
        double thickness = 2.5e-4, stacked = 0.5 * thickness + 0.05 * thickness + 2 * 1.05 * thickness;
        double top = trial.scene().centroid(trial.scene().startState(rested, 0), 1)[2];
        assertTrue(top < stacked && top > stacked - 3 * 0.05 * thickness, "top card's centre at " + top + " m, stacked at " + stacked);

        // a new trial of the same configs reads the checkpoint instead of warming up: the same state, bit for bit
        SimState read = fewCards(dir, Map.of()).restedStack();
        assertTrue(read.sameAs(rested), "the checkpoint restores the rested stack bit for bit");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        rested.write(new DataOutputStream(bytes));
        assertTrue(SimState.read(new DataInputStream(new ByteArrayInputStream(bytes.toByteArray()))).sameAs(rested));
    }

    @Test
    void theKeyFollowsTheConfigsAndAStaleCheckpointIsRefused(@TempDir Path dir) throws Exception {
        LiftTrial made = fewCards(dir, Map.of());
        made.restedStack();
        // what shapes the warm-up changes the key; which cards move in a trial, or a comment, does not
        Path sameKey = fewCards(dir, Map.of("double-lift.stack.freeCards", "3", "double-lift.stack.comment", "\"another\"")).checkpointFile();
        assertEquals(made.checkpointFile(), sameKey);
        LiftTrial other = fewCards(dir, Map.of("double-lift.card.gapFraction", "0.1"));
        assertNotEquals(made.checkpointFile(), other.checkpointFile(), "another gap fraction is another stack");
        assertNotEquals(made.checkpointFile(), fewCards(dir, Map.of("solver.timeStep", "0.005")).checkpointFile());
        // a checkpoint under another configs' name (copied, renamed) is refused, not reused
        Files.copy(made.checkpointFile(), other.checkpointFile());
        ConfigException e = assertThrows(ConfigException.class, other::restedStack);
        assertTrue(e.getMessage().contains("stale checkpoint"), e.getMessage());
    }
}
