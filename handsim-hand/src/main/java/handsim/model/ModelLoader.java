package handsim.model;

import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.math.Quat;
import handsim.math.Vec3;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Loads and validates a model file (schema in {@code models/README.md}). Every inconsistency
 * fails with a {@link ConfigException} that names the field and the bad value; a model that
 * loads is complete and consistent.
 */
public final class ModelLoader {

    /** Poses the controller needs. */
    public static final List<String> REQUIRED_POSES = List.of("neutral", "open", "closed");
    /** Sites the controller needs. */
    public static final List<String> REQUIRED_SITES = List.of("palm_center");

    /*
     * Sanity limits of an arm and hand (SI): a body from a gram to 100 kg; a shape's radius,
     * side, length or offset from 0.1 mm (thinner ones fall through contacts at h = 0.2 ms) to
     * 2 m (larger is no body part, nor anything a hand catches); a joint torque up to 1000 N m
     * (a strong shoulder gives about 100); passive damping up to 100 N m s/rad.
     */
    static final double MIN_BODY_MASS = 1e-3, MAX_BODY_MASS = 100;
    static final double MIN_SIZE = 1e-4, MAX_SIZE = 2;
    static final double MAX_TORQUE = 1000;
    static final double MAX_PASSIVE_DAMPING = 100;

    private ModelLoader() {
    }

    public static HandModel load(Path file) {
        return parse(Json.load(file));
    }

    /** A model checked against the project's {@code models/physiology.json} ({@link Physiology}). */
    public static HandModel parse(Json root) {
        return parse(root, Physiology.load());
    }

    /**
     * A model checked against {@code physiology}, the text of {@code models/physiology.json} as a
     * run read it ({@link #physiologyText}): for a machine without the project's files, such as a
     * cluster's executor.
     */
    public static HandModel parse(Json root, String physiology) {
        return parse(root, Physiology.parse(Json.parse(Physiology.FILE, physiology)));
    }

    /** The project's {@code models/physiology.json} as JSON text, to travel with a model. */
    public static String physiologyText() {
        return Json.load(Home.resolve(Physiology.FILE)).node().toString();
    }

    private static HandModel parse(Json root, Physiology physiology) {
        String name = root.string("name");
        root.allow("description", "units", "sources", "comment");
        List<Body> bodies = new ArrayList<>();
        List<Joint> joints = new ArrayList<>();
        List<Dof> dofs = new ArrayList<>();
        Map<String, Integer> bodyIndex = new HashMap<>();
        Map<String, Integer> jointNames = new HashMap<>();
        Map<String, Integer> dofNames = new HashMap<>();

        List<Json> bodyNodes = root.array("bodies");
        if (bodyNodes.isEmpty()) {
            throw root.fieldError("bodies", "at least one body is required");
        }
        for (Json b : bodyNodes) {
            b.allow("comment");
            String bodyName = b.string("name");
            if (bodyName.isBlank() || bodyIndex.containsKey(bodyName)) {
                throw b.fieldError("name", bodyName.isBlank() ? "must not be empty" : "duplicate body name \"" + bodyName + "\"");
            }
            String parentName = b.string("parent");
            int parent;
            if (parentName.equals("world")) {
                parent = -1;
                if (bodies.stream().anyMatch(x -> x.parent() < 0)) {
                    throw b.fieldError("parent", "only one body may hang from the world (the fixed shoulder), got a second: \"" + bodyName + "\"");
                }
            } else {
                Integer p = bodyIndex.get(parentName);
                if (p == null) {
                    throw b.fieldError("parent", "unknown body \"" + parentName + "\" (a parent must be declared before its children, or be \"world\")");
                }
                parent = p;
            }
            int index = bodies.size();
            Vec3 parentOrigin = parent < 0 ? Vec3.ZERO : bodies.get(parent).origin();

            Json j = b.get("joint");
            j.allow("comment");
            String jointName = j.string("name");
            if (jointNames.containsKey(jointName)) {
                throw j.fieldError("name", "duplicate joint name \"" + jointName + "\"");
            }
            JointType type;
            String typeName = j.choice("type", "hinge", "universal", "ball");
            type = JointType.parse(typeName);
            Vec3 anchor = parentOrigin.plus(j.vec3("anchor"));
            List<Json> dofNodes = j.array("dofs");
            if (dofNodes.size() != type.dofCount()) {
                throw j.fieldError("dofs", "a " + typeName + " joint has " + type.dofCount() + " dofs, got " + dofNodes.size());
            }
            Joint joint = new Joint(joints.size(), jointName, type, parent, index, anchor, dofs.size());
            List<Vec3> axes = new ArrayList<>();
            for (int s = 0; s < dofNodes.size(); s++) {
                Json d = dofNodes.get(s);
                d.allow("comment");
                String dofName = d.string("name");
                if (dofNames.containsKey(dofName)) {
                    throw d.fieldError("name", "duplicate dof name \"" + dofName + "\"");
                }
                Vec3 axis = d.vec3("axis");
                if (axis.norm() < 1e-9) {
                    throw d.fieldError("axis", "must be a non-zero vector, got " + axis);
                }
                axis = axis.normalized();
                double[] range = d.range("rangeDeg");
                if (!(range[0] < range[1])) {
                    throw d.fieldError("rangeDeg", "lower limit must be below upper limit, got [" + range[0] + ", " + range[1] + "]");
                }
                physiology.check(d, "rangeDeg", dofName, range);
                if (type == JointType.BALL && s == 1 && (range[0] <= -90 || range[1] >= 90)) {
                    throw d.fieldError("rangeDeg", "the middle angle of a ball joint must stay inside (-90, 90) degrees (Euler singularity), got ["
                            + range[0] + ", " + range[1] + "]");
                }
                double[] torque = torqueLimits(d);
                double passive = d.has("passiveDamping") ? d.number("passiveDamping", 0, MAX_PASSIVE_DAMPING)
                        : d.number("passiveDamping", 0.0);
                d.requireNoUnknownFields();
                Dof dof = new Dof(dofs.size(), dofName, joint.index(), s, axis, Math.toRadians(range[0]),
                        Math.toRadians(range[1]), torque[0], torque[1], passive);
                dofNames.put(dofName, dof.index());
                dofs.add(dof);
                axes.add(axis);
            }
            for (int s = 0; s < axes.size(); s++) {
                for (int t = s + 1; t < axes.size(); t++) {
                    double dot = axes.get(s).dot(axes.get(t));
                    if (Math.abs(dot) > 1e-3) {
                        throw j.fieldError("dofs", "axes of a " + typeName + " joint must be perpendicular, dofs " + s + " and " + t
                                + " have cos = " + String.format("%.4f", dot));
                    }
                }
            }
            orthonormalize(dofs, joint.firstDof(), axes.size());
            j.requireNoUnknownFields();
            jointNames.put(jointName, joint.index());
            joints.add(joint);

            double mass = b.number("mass", MIN_BODY_MASS, MAX_BODY_MASS);
            List<Shape> shapes = new ArrayList<>();
            for (Json g : b.array("shapes")) {
                shapes.add(parseShape(g));
            }
            if (shapes.isEmpty()) {
                throw b.fieldError("shapes", "at least one shape is needed (collision and inertia)");
            }
            boolean collides = b.bool("collides", true);
            MassProperties mp = MassProperties.of(shapes, mass);
            if (!mp.inertia().isPlausible()) {
                throw b.fieldError("shapes", "shapes give an implausible inertia " + mp.inertia());
            }
            b.requireNoUnknownFields();
            bodyIndex.put(bodyName, index);
            bodies.add(new Body(index, bodyName, parent, joint.index(), anchor, mp, shapes, collides));
        }

        Map<String, Integer> breakdown = parseBreakdown(root, dofs.size());
        Map<String, Site> sites = parseSites(root, bodyIndex);
        Map<String, Pose> poses = parsePoses(root, dofNames, dofs);
        root.requireNoUnknownFields();
        return new HandModel(name, bodies, joints, dofs, sites, poses, breakdown);
    }

    /**
     * Makes the axes of a multi-DOF joint exactly orthonormal (Gram-Schmidt in DOF order) after
     * they passed the perpendicularity check, so that rounding in the file does not bias rates.
     */
    private static void orthonormalize(List<Dof> dofs, int first, int count) {
        for (int s = 1; s < count; s++) {
            Dof d = dofs.get(first + s);
            Vec3 a = d.axis();
            for (int t = 0; t < s; t++) {
                Vec3 b = dofs.get(first + t).axis();
                a = a.minus(b.times(a.dot(b)));
            }
            dofs.set(first + s, new Dof(d.index(), d.name(), d.joint(), d.slot(), a.normalized(), d.lower(), d.upper(),
                    d.torqueMin(), d.torqueMax(), d.passiveDamping()));
        }
    }

    /** "torqueLimit": a number L (symmetric, [-L, L]) or [min, max] with min < 0 < max. */
    private static double[] torqueLimits(Json d) {
        Json t = d.get("torqueLimit");
        if (t.node().isNumber()) {
            double limit = d.positive("torqueLimit");
            if (limit > MAX_TORQUE) {
                throw t.error("must be in (0, " + Json.show(MAX_TORQUE) + "] N m, got " + Json.show(limit));
            }
            return new double[] {-limit, limit};
        }
        double[] r = t.asNumbers(2);
        if (!(r[0] < 0 && r[1] > 0 && r[0] >= -MAX_TORQUE && r[1] <= MAX_TORQUE)) {
            throw t.error("torque limits must be [min, max] with -" + Json.show(MAX_TORQUE) + " <= min < 0 < max <= "
                    + Json.show(MAX_TORQUE) + " N m, got [" + Json.show(r[0]) + ", " + Json.show(r[1]) + "]");
        }
        return r;
    }

    /** Parses one shape; also used for the thrown objects in {@code configs/objects}. */
    public static Shape parseShape(Json g) {
        g.allow("comment");
        String type = g.choice("type", "capsule", "cylinder", "box", "sphere");
        Shape shape = switch (type) {
            case "capsule", "cylinder" -> {
                Vec3 a = position(g, "from"), b = position(g, "to");
                double r = g.number("radius", MIN_SIZE, MAX_SIZE);
                if (a.distance(b) < 1e-9) {
                    throw g.fieldError("to", type + " end points must differ, got " + b);
                }
                yield type.equals("capsule") ? new Shape.Capsule(a, b, r) : new Shape.Cylinder(a, b, r);
            }
            case "box" -> {
                Vec3 size = g.vec3("size");
                if (!(Math.min(size.x(), Math.min(size.y(), size.z())) >= MIN_SIZE
                        && Math.max(size.x(), Math.max(size.y(), size.z())) <= MAX_SIZE)) {
                    throw g.fieldError("size", "box sides must be in [" + Json.show(MIN_SIZE) + ", " + Json.show(MAX_SIZE)
                            + "] m, got " + size);
                }
                Vec3 rot = g.vec3("rotationDeg", Vec3.ZERO);
                yield new Shape.Box(g.has("center") ? position(g, "center") : Vec3.ZERO, size,
                        Quat.fromRotationVector(rot.times(Math.PI / 180)));
            }
            case "sphere" -> new Shape.Sphere(g.has("center") ? position(g, "center") : Vec3.ZERO,
                    g.number("radius", MIN_SIZE, MAX_SIZE));
            default -> throw new IllegalStateException(type);
        };
        g.requireNoUnknownFields();
        return shape;
    }

    /** A point of a shape (m, in its body's frame), at most {@link #MAX_SIZE} from the origin. */
    private static Vec3 position(Json g, String name) {
        Vec3 p = g.vec3(name);
        if (!(p.norm() <= MAX_SIZE)) {
            throw g.fieldError(name, "must lie within " + Json.show(MAX_SIZE) + " m of the frame's origin, got " + p);
        }
        return p;
    }

    private static Map<String, Integer> parseBreakdown(Json root, int actualDofs) {
        Json bd = root.get("dofBreakdown");
        Map<String, Integer> out = new LinkedHashMap<>();
        int sum = 0;
        for (String group : bd.fieldNames()) {
            int n = bd.integer(group, 0, 1000);
            out.put(group, n);
            if (!group.equals("total")) {
                sum += n;
            }
        }
        if (!out.containsKey("total")) {
            throw root.fieldError("dofBreakdown", "must state a \"total\"");
        }
        int total = out.get("total");
        if (sum != total) {
            throw root.fieldError("dofBreakdown", "groups sum to " + sum + " but total says " + total);
        }
        if (actualDofs != total) {
            throw root.fieldError("dofBreakdown", "the joints define " + actualDofs + " DOF but the breakdown says " + total);
        }
        return out;
    }

    private static Map<String, Site> parseSites(Json root, Map<String, Integer> bodyIndex) {
        Json sitesNode = root.get("sites");
        Map<String, Site> sites = new LinkedHashMap<>();
        for (String siteName : sitesNode.fieldNames()) {
            Json s = sitesNode.get(siteName);
            s.allow("comment");
            String bodyName = s.string("body");
            Integer body = bodyIndex.get(bodyName);
            if (body == null) {
                throw s.fieldError("body", "unknown body \"" + bodyName + "\"");
            }
            Vec3 x = s.vec3("x"), y = s.vec3("y");
            if (x.norm() < 1e-9 || y.norm() < 1e-9 || Math.abs(x.normalized().dot(y.normalized())) > 1e-3) {
                throw s.error("x and y must be non-zero and perpendicular, got x " + x + ", y " + y);
            }
            Vec3 ex = x.normalized(), ey = y.normalized();
            sites.put(siteName, new Site(siteName, body, s.vec3("position"), Quat.fromFrame(ex, ey, ex.cross(ey))));
            s.requireNoUnknownFields();
        }
        for (String required : REQUIRED_SITES) {
            if (!sites.containsKey(required)) {
                throw root.fieldError("sites", "the controller needs a site named \"" + required + "\"");
            }
        }
        return sites;
    }

    private static Map<String, Pose> parsePoses(Json root, Map<String, Integer> dofNames, List<Dof> dofs) {
        Json posesNode = root.get("poses");
        Map<String, Pose> poses = new LinkedHashMap<>();
        for (String poseName : posesNode.fieldNames()) {
            Json p = posesNode.get(poseName);
            List<String> names = p.fieldNames();
            int[] idx = new int[names.size()];
            double[] angles = new double[names.size()];
            List<Integer> order = new ArrayList<>();
            Map<Integer, Double> byDof = new HashMap<>();
            for (String dofName : names) {
                if (dofName.equals("comment")) {
                    continue;
                }
                Integer d = dofNames.get(dofName);
                if (d == null) {
                    throw p.fieldError(dofName, "unknown dof \"" + dofName + "\"");
                }
                double deg = p.number(dofName);
                Dof dof = dofs.get(d);
                double rad = Math.toRadians(deg);
                if (rad < dof.lower() - 1e-9 || rad > dof.upper() + 1e-9) {
                    throw p.fieldError(dofName, "angle " + deg + " deg lies outside the dof's range ["
                            + Math.toDegrees(dof.lower()) + ", " + Math.toDegrees(dof.upper()) + "]");
                }
                order.add(d);
                byDof.put(d, rad);
            }
            order.sort(Integer::compare);
            idx = new int[order.size()];
            angles = new double[order.size()];
            for (int i = 0; i < order.size(); i++) {
                idx[i] = order.get(i);
                angles[i] = byDof.get(order.get(i));
            }
            poses.put(poseName, new Pose(poseName, idx, angles));
        }
        for (String required : REQUIRED_POSES) {
            if (!poses.containsKey(required)) {
                throw root.fieldError("poses", "the controller needs a pose named \"" + required + "\"");
            }
        }
        return poses;
    }
}
