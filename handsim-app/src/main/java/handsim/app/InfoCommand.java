package handsim.app;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.config.Json;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.model.Body;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.ModelLoader;
import handsim.model.Shape;
import handsim.report.Outputs;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code handsim info}: the model's DOF breakdown, bodies, masses and limits. */
@Command(name = "info", mixinStandardHelpOptions = true,
        description = "Print the arm+hand model: DOF breakdown, bodies, masses, joint limits and torque limits.")
final class InfoCommand implements Callable<Integer> {

    @Option(names = "--model", paramLabel = "FILE", description = "model file (default: models/arm_hand.json)")
    Path modelFile;

    @Option(names = "--json", paramLabel = "FILE", description = "also write the information as JSON")
    Path json;

    @Option(names = "--pose", paramLabel = "NAME", description = "also give world positions of the bodies and shapes in this pose (neutral, open, closed; "
            + "zero: every angle 0, the model's rest configuration)")
    String pose;

    @Override
    public Integer call() throws Exception {
        new OutputPaths().file("--json", json).check();
        HandModel model = ModelLoader.load(modelFile != null ? modelFile : Home.defaultModel());
        ObjectNode out = describe(model);
        if (pose != null) {
            out.set("pose", posed(model, pose));
        }
        print(model);
        if (json != null) {
            Outputs.writeJson(json, out);
            System.out.println("wrote " + json);
        }
        return 0;
    }

    private static void print(HandModel m) {
        System.out.printf("model %s: %d bodies, %d DOF, %.3f kg%n", m.name(), m.bodyCount(), m.dofCount(), m.totalMass());
        System.out.println("DOF breakdown:");
        m.dofBreakdown().forEach((k, v) -> System.out.printf("  %-62s %2d%n", k, v));
        System.out.println("bodies (mass kg, parent, joint, driven mass kg):");
        for (Body b : m.bodies()) {
            Joint j = m.joints().get(b.joint());
            System.out.printf("  %-20s %6.3f  %-20s %-10s %-9s m_joint %.3f%n", b.name(), b.mass().mass(),
                    b.parent() < 0 ? "world" : m.bodies().get(b.parent()).name(), j.name(), j.type().name().toLowerCase(),
                    m.drivenMass(j.index()));
        }
        System.out.println("dofs (range deg, torque N m):");
        for (Dof d : m.dofs()) {
            System.out.printf("  %2d %-24s [%7.1f, %7.1f]  [%6.2f, %6.2f]%n", d.index(), d.name(), Math.toDegrees(d.lower()),
                    Math.toDegrees(d.upper()), d.torqueMin(), d.torqueMax());
        }
    }

    static ObjectNode describe(HandModel m) {
        JsonNodeFactory f = JsonNodeFactory.instance;
        ObjectNode out = f.objectNode();
        out.put("model", m.name());
        out.put("dof", m.dofCount());
        out.put("bodies_count", m.bodyCount());
        out.put("total_mass_kg", m.totalMass());
        ObjectNode breakdown = out.putObject("dof_breakdown");
        m.dofBreakdown().forEach(breakdown::put);
        ArrayNode bodies = out.putArray("bodies");
        for (Body b : m.bodies()) {
            Joint j = m.joints().get(b.joint());
            ObjectNode o = bodies.addObject();
            o.put("name", b.name());
            o.put("parent", b.parent() < 0 ? "world" : m.bodies().get(b.parent()).name());
            o.put("mass_kg", b.mass().mass());
            o.set("com_m", Json.array(b.mass().com().toArray()));
            o.put("joint", j.name());
            o.put("joint_type", j.type().name().toLowerCase());
            o.put("driven_mass_kg", m.drivenMass(j.index()));
        }
        ArrayNode dofs = out.putArray("dofs");
        for (Dof d : m.dofs()) {
            ObjectNode o = dofs.addObject();
            o.put("name", d.name());
            o.put("joint", m.joints().get(d.joint()).name());
            o.set("range_deg", Json.array(Math.toDegrees(d.lower()), Math.toDegrees(d.upper())));
            o.set("torque_limit_nm", Json.array(d.torqueMin(), d.torqueMax()));
        }
        return out;
    }

    /** The pose name of the model's rest configuration, every angle 0 (where BVH's zero frame puts the joints). */
    static final String ZERO_POSE = "zero";

    /** World geometry of the model in a named pose: body frames and capsule end points. */
    static ObjectNode posed(HandModel m, String poseName) {
        double[] q = poseName.equals(ZERO_POSE) ? new double[m.dofCount()] : m.poseVector("neutral");
        if (!poseName.equals(ZERO_POSE)) {
            m.pose(poseName).applyTo(q);
        }
        Frame[] frames = new Kinematics(m).forward(q);
        ObjectNode out = JsonNodeFactory.instance.objectNode();
        out.put("name", poseName);
        ArrayNode bodies = out.putArray("bodies");
        for (Body b : m.bodies()) {
            ObjectNode o = bodies.addObject();
            Frame fr = frames[b.index()];
            o.put("name", b.name());
            o.set("origin", Json.array(fr.origin().toArray()));
            ArrayNode caps = o.putArray("capsules");
            for (Shape s : b.shapes()) {
                if (s instanceof Shape.Capsule c) {
                    ObjectNode co = caps.addObject();
                    co.set("a", Json.array(fr.pointToWorld(c.a()).toArray()));
                    co.set("b", Json.array(fr.pointToWorld(c.b()).toArray()));
                    co.put("r", c.radius());
                }
            }
        }
        Map<String, handsim.model.Site> sites = m.sites();
        ObjectNode so = out.putObject("sites");
        sites.forEach((name, s) -> {
            Frame fr = new Kinematics(m).siteFrame(s, q);
            ObjectNode o = so.putObject(name);
            o.set("origin", Json.array(fr.origin().toArray()));
            o.set("x", Json.array(fr.rotation().xAxis().toArray()));
            o.set("y", Json.array(fr.rotation().yAxis().toArray()));
            o.set("z", Json.array(fr.rotation().zAxis().toArray()));
        });
        return out;
    }
}
