package handsim.model;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The immutable arm+hand model: bodies in topological order (every parent before its
 * children), one joint per body, the DOF vector in body order, named sites and poses.
 * Build it with {@link ModelLoader}.
 */
public final class HandModel {

    private final String name;
    private final List<Body> bodies;
    private final List<Joint> joints;
    private final List<Dof> dofs;
    private final Map<String, Site> sites;
    private final Map<String, Pose> poses;
    private final Map<String, Integer> dofBreakdown;
    private final Map<String, Integer> bodyIndex = new HashMap<>();
    private final Map<String, Integer> jointIndex = new HashMap<>();
    private final Map<String, Integer> dofIndex = new HashMap<>();
    private final double[] drivenMass;

    HandModel(String name, List<Body> bodies, List<Joint> joints, List<Dof> dofs, Map<String, Site> sites,
            Map<String, Pose> poses, Map<String, Integer> dofBreakdown) {
        this.name = name;
        this.bodies = List.copyOf(bodies);
        this.joints = List.copyOf(joints);
        this.dofs = List.copyOf(dofs);
        this.sites = Collections.unmodifiableMap(new LinkedHashMap<>(sites));
        this.poses = Collections.unmodifiableMap(new LinkedHashMap<>(poses));
        this.dofBreakdown = Collections.unmodifiableMap(new LinkedHashMap<>(dofBreakdown));
        bodies.forEach(b -> bodyIndex.put(b.name(), b.index()));
        joints.forEach(j -> jointIndex.put(j.name(), j.index()));
        dofs.forEach(d -> dofIndex.put(d.name(), d.index()));
        // eq. (4): m_joint is the total mass driven by the joint, i.e. of the child's subtree
        drivenMass = new double[joints.size()];
        for (int b = bodies.size() - 1; b >= 0; b--) {
            Body body = bodies.get(b);
            drivenMass[body.joint()] += body.mass().mass();
            if (body.parent() >= 0) {
                drivenMass[bodies.get(body.parent()).joint()] += drivenMass[body.joint()];
            }
        }
    }

    public String name() {
        return name;
    }

    public List<Body> bodies() {
        return bodies;
    }

    public List<Joint> joints() {
        return joints;
    }

    public List<Dof> dofs() {
        return dofs;
    }

    public int dofCount() {
        return dofs.size();
    }

    public int bodyCount() {
        return bodies.size();
    }

    public Map<String, Site> sites() {
        return sites;
    }

    public Map<String, Pose> poses() {
        return poses;
    }

    /** The breakdown of the DOF count by anatomical group, as written in the model file. */
    public Map<String, Integer> dofBreakdown() {
        return dofBreakdown;
    }

    public Body body(String bodyName) {
        return bodies.get(lookup(bodyIndex, bodyName, "body"));
    }

    public Joint joint(String jointName) {
        return joints.get(lookup(jointIndex, jointName, "joint"));
    }

    public Dof dof(String dofName) {
        return dofs.get(lookup(dofIndex, dofName, "dof"));
    }

    public boolean hasBody(String bodyName) {
        return bodyIndex.containsKey(bodyName);
    }

    public Site site(String siteName) {
        Site s = sites.get(siteName);
        if (s == null) {
            throw new IllegalArgumentException("model " + name + " has no site \"" + siteName + "\"; sites: " + sites.keySet());
        }
        return s;
    }

    public Pose pose(String poseName) {
        Pose p = poses.get(poseName);
        if (p == null) {
            throw new IllegalArgumentException("model " + name + " has no pose \"" + poseName + "\"; poses: " + poses.keySet());
        }
        return p;
    }

    private int lookup(Map<String, Integer> index, String key, String kind) {
        Integer i = index.get(key);
        if (i == null) {
            throw new IllegalArgumentException("model " + name + " has no " + kind + " named \"" + key + "\"");
        }
        return i;
    }

    /** Total mass (kg) of the bodies below joint {@code joint}: m_joint of eq. (4). */
    public double drivenMass(int joint) {
        return drivenMass[joint];
    }

    public double totalMass() {
        return bodies.stream().mapToDouble(b -> b.mass().mass()).sum();
    }

    /** The joints from the root down to {@code body}'s own joint, root first. */
    public List<Joint> chainTo(int body) {
        List<Joint> chain = new ArrayList<>();
        for (int b = body; b >= 0; b = bodies.get(b).parent()) {
            chain.add(0, joints.get(bodies.get(b).joint()));
        }
        return chain;
    }

    /** True when {@code ancestor} is {@code body} or lies on its path to the root. */
    public boolean isAncestorOrSelf(int ancestor, int body) {
        for (int b = body; b >= 0; b = bodies.get(b).parent()) {
            if (b == ancestor) {
                return true;
            }
        }
        return false;
    }

    /** The model's DOF vector with every DOF at 0 and {@code pose} applied. */
    public double[] poseVector(String poseName) {
        double[] q = new double[dofCount()];
        pose(poseName).applyTo(q);
        return q;
    }
}
