package handsim.cards.sim;

import handsim.cards.contact.CollisionMesh;
import handsim.cards.energy.Bending;
import handsim.cards.energy.Membrane;
import handsim.cards.energy.TetElasticity;
import handsim.cards.linalg.SparseSpdSystem;
import handsim.cards.mesh.TetMesh;
import handsim.cards.mesh.ShellMesh;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;

/**
 * The immutable model of a card scene, compiled once from its bodies: rest positions, lumped
 * masses, which nodes are bone (Dirichlet), the elastic energies, what can touch, and the node
 * pairs the elastic energies couple. All changing values live in {@link SimState}.
 */
public final class SoftWorld {

    final double[] rest;
    final double[] mass;
    final boolean[] dirichlet;
    /** system index of each node, −1 for Dirichlet nodes */
    final int[] freeIndex;
    final int freeCount;
    final List<SoftBody> bodies;
    /** bone nodes of each fingertip, in fingertip order */
    final int[][] boneNodes;
    final TetElasticity tets;
    final Membrane membrane;
    final Bending bending;
    final CollisionMesh collision;
    /** sorted pair keys (system indices) of the elastic couplings */
    final long[] elasticPairs;
    final double bboxDiagonal;
    private final List<handsim.cards.energy.Energy> elastic;

    private SoftWorld(Builder b) {
        int n = b.nodes.size() / 3;
        rest = b.nodes.stream().mapToDouble(Double::doubleValue).toArray();
        mass = new double[n];
        dirichlet = new boolean[n];
        for (int i : b.bone) {
            dirichlet[i] = true;
        }
        for (int i : b.fixed) {
            dirichlet[i] = true;
        }
        freeIndex = new int[n];
        int f = 0;
        for (int i = 0; i < n; i++) {
            freeIndex[i] = dirichlet[i] ? -1 : f++;
        }
        freeCount = f;
        bodies = List.copyOf(b.bodies);
        boneNodes = b.boneGroups.toArray(new int[0][]);
        // fingertips: fixed-corotated tets, lumped mass ρV/4; a tet whose four nodes are all bone
        // moves rigidly, its energy is constant, and only its mass is kept
        int[] allTets = b.tets.stream().mapToInt(Integer::intValue).toArray();
        List<Integer> soft = new ArrayList<>();
        for (int t = 0; t < allTets.length / 4; t++) {
            double volume = TetElasticity.volume(rest, allTets, t);
            for (int k = 0; k < 4; k++) {
                mass[allTets[4 * t + k]] += b.tetDensity.get(t) * volume / 4;
            }
            boolean anyFree = false;
            for (int k = 0; k < 4; k++) {
                anyFree |= !dirichlet[allTets[4 * t + k]];
            }
            if (anyFree) {
                soft.add(t);
            }
        }
        int[] tetArr = new int[4 * soft.size()];
        double[] tetMu = new double[soft.size()];
        double[] tetLambda = new double[soft.size()];
        for (int i = 0; i < soft.size(); i++) {
            int t = soft.get(i);
            System.arraycopy(allTets, 4 * t, tetArr, 4 * i, 4);
            tetMu[i] = b.tetMu.get(t);
            tetLambda[i] = b.tetLambda.get(t);
        }
        tets = soft.isEmpty() ? null : new TetElasticity(tetArr, rest, tetMu, tetLambda);
        // cards: StVK membrane and hinge bending, lumped mass ρtA/3
        // cards: StVK membrane and hinge bending, lumped mass ρtA/3; a fixed card's triangles and
        // hinges have constant energy, and only their mass is kept
        int[] allTris = b.tris.stream().mapToInt(Integer::intValue).toArray();
        List<Integer> softTris = new ArrayList<>();
        for (int t = 0; t < allTris.length / 3; t++) {
            ShellMaterial m = b.triMaterial.get(t);
            double area = triangleArea(rest, allTris[3 * t], allTris[3 * t + 1], allTris[3 * t + 2]);
            for (int k = 0; k < 3; k++) {
                mass[allTris[3 * t + k]] += m.density() * m.thickness() * area / 3;
            }
            if (anyFree(allTris, 3, t)) {
                softTris.add(t);
            }
        }
        int nf = softTris.size();
        int[] triArr = new int[3 * nf];
        double[] young = new double[nf];
        double[] poisson = new double[nf];
        double[] thick = new double[nf];
        for (int i = 0; i < nf; i++) {
            int t = softTris.get(i);
            System.arraycopy(allTris, 3 * t, triArr, 3 * i, 3);
            ShellMaterial m = b.triMaterial.get(t);
            young[i] = m.young();
            poisson[i] = m.poisson();
            thick[i] = m.thickness();
        }
        membrane = nf == 0 ? null : new Membrane(triArr, rest, young, poisson, thick);
        int[] allHinges = b.hinges.stream().mapToInt(Integer::intValue).toArray();
        List<Integer> softHinges = new ArrayList<>();
        for (int h = 0; h < allHinges.length / 4; h++) {
            if (anyFree(allHinges, 4, h)) {
                softHinges.add(h);
            }
        }
        int[] hingeArr = new int[4 * softHinges.size()];
        double[] hingeK = new double[softHinges.size()];
        for (int i = 0; i < hingeK.length; i++) {
            System.arraycopy(allHinges, 4 * softHinges.get(i), hingeArr, 4 * i, 4);
            hingeK[i] = b.hingeStiffness.get(softHinges.get(i));
        }
        bending = hingeArr.length == 0 ? null : new Bending(hingeArr, rest, hingeK);
        collision = new CollisionMesh(
                b.contactVertices.stream().mapToInt(Integer::intValue).toArray(),
                b.contactEdges.stream().mapToInt(Integer::intValue).toArray(),
                b.contactFaces.stream().mapToInt(Integer::intValue).toArray(),
                b.bodyOfNode.stream().mapToInt(Integer::intValue).toArray(),
                b.halfThickness.stream().mapToDouble(Double::doubleValue).toArray(),
                toBooleans(b.selfContact), rest, toBooleans(b.isCard), b.friction, b.groundHeight, dirichlet);
        List<handsim.cards.energy.Energy> terms = new ArrayList<>();
        for (handsim.cards.energy.Energy term : new handsim.cards.energy.Energy[] {tets, membrane, bending}) {
            if (term != null) {
                terms.add(term);
            }
        }
        elastic = List.copyOf(terms);
        TreeSet<Long> pairs = new TreeSet<>();
        couple(pairs, tetArr, 4);
        couple(pairs, triArr, 3);
        couple(pairs, hingeArr, 4);
        elasticPairs = pairs.stream().mapToLong(Long::longValue).toArray();
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < n; i++) {
            for (int c = 0; c < 3; c++) {
                lo[c] = Math.min(lo[c], rest[3 * i + c]);
                hi[c] = Math.max(hi[c], rest[3 * i + c]);
            }
        }
        bboxDiagonal = Math.sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
    }

    /** Whether element e (k nodes each) has a node that is not Dirichlet. */
    private boolean anyFree(int[] elems, int k, int e) {
        for (int i = 0; i < k; i++) {
            if (!dirichlet[elems[k * e + i]]) {
                return true;
            }
        }
        return false;
    }

    private void couple(TreeSet<Long> pairs, int[] elems, int k) {
        for (int e = 0; e < elems.length / k; e++) {
            for (int i = 0; i < k; i++) {
                for (int j = i + 1; j < k; j++) {
                    int a = freeIndex[elems[k * e + i]];
                    int c = freeIndex[elems[k * e + j]];
                    if (a >= 0 && c >= 0 && a != c) {
                        pairs.add(SparseSpdSystem.pairKey(a, c));
                    }
                }
            }
        }
    }

    private static boolean[] toBooleans(List<Boolean> list) {
        boolean[] out = new boolean[list.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = list.get(i);
        }
        return out;
    }

    static double triangleArea(double[] x, int a, int b, int c) {
        double[] u = {x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1], x[3 * b + 2] - x[3 * a + 2]};
        double[] w = {x[3 * c] - x[3 * a], x[3 * c + 1] - x[3 * a + 1], x[3 * c + 2] - x[3 * a + 2]};
        double cx = u[1] * w[2] - u[2] * w[1];
        double cy = u[2] * w[0] - u[0] * w[2];
        double cz = u[0] * w[1] - u[1] * w[0];
        return 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
    }

    public int nodeCount() {
        return mass.length;
    }

    /** The elastic energies present (fingertip tets, card membrane, card bending). */
    List<handsim.cards.energy.Energy> elasticEnergies() {
        return elastic;
    }

    public int freeNodeCount() {
        return freeCount;
    }

    public List<SoftBody> bodies() {
        return bodies;
    }

    public SoftBody body(String name) {
        return bodies.stream().filter(b -> b.name().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no body named " + name));
    }

    public double[] restPositions() {
        return rest.clone();
    }

    public double mass(int node) {
        return mass[node];
    }

    public boolean isBone(int node) {
        return dirichlet[node];
    }

    public int fingertipCount() {
        return boneNodes.length;
    }


    public CollisionMesh collision() {
        return collision;
    }

    /** The state at rest: rest positions, zero velocity. */
    public SimState restState() {
        return new SimState(rest, new double[rest.length]);
    }

    /** A rigid placement: rotation (row-major 3x3) then translation. */
    public record Placement(double[] rotation, double[] translation) {
        public static Placement at(double x, double y, double z) {
            return new Placement(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, new double[] {x, y, z});
        }

        double[] apply(double[] v, int i) {
            double[] r = rotation;
            double px = v[3 * i];
            double py = v[3 * i + 1];
            double pz = v[3 * i + 2];
            return new double[] {
                r[0] * px + r[1] * py + r[2] * pz + translation[0],
                r[3] * px + r[4] * py + r[5] * pz + translation[1],
                r[6] * px + r[7] * py + r[8] * pz + translation[2],
            };
        }
    }

    /** Assembles a world body by body. */
    public static final class Builder {
        private final List<Double> nodes = new ArrayList<>();
        private final List<SoftBody> bodies = new ArrayList<>();
        private final List<Integer> bone = new ArrayList<>();
        private final List<Integer> fixed = new ArrayList<>();
        private final List<int[]> boneGroups = new ArrayList<>();
        private final List<Integer> tets = new ArrayList<>();
        private final List<Double> tetMu = new ArrayList<>();
        private final List<Double> tetLambda = new ArrayList<>();
        private final List<Double> tetDensity = new ArrayList<>();
        private final List<Integer> tris = new ArrayList<>();
        private final List<ShellMaterial> triMaterial = new ArrayList<>();
        private final List<Integer> hinges = new ArrayList<>();
        private final List<Double> hingeStiffness = new ArrayList<>();
        private final List<Integer> contactVertices = new ArrayList<>();
        private final List<Integer> contactEdges = new ArrayList<>();
        private final List<Integer> contactFaces = new ArrayList<>();
        private final List<Integer> bodyOfNode = new ArrayList<>();
        private final List<Double> halfThickness = new ArrayList<>();
        private final List<Boolean> selfContact = new ArrayList<>();
        private final List<Boolean> isCard = new ArrayList<>();
        private double groundHeight = Double.NaN;
        private CollisionMesh.FrictionTable friction = new CollisionMesh.FrictionTable(0, 0, 0);

        /** Friction coefficients of the scene's contacts. */
        public Builder friction(CollisionMesh.FrictionTable table) {
            this.friction = table;
            return this;
        }

        private int addNodes(double[] v, Placement at) {
            int first = nodes.size() / 3;
            for (int i = 0; i < v.length / 3; i++) {
                for (double c : at.apply(v, i)) {
                    nodes.add(c);
                }
                bodyOfNode.add(bodies.size());
            }
            return first;
        }

        /** A card: every vertex, edge and triangle can touch, itself included. */
        public Builder card(String name, ShellMesh mesh, ShellMaterial material, Placement at) {
            int first = addNodes(mesh.vertices(), at);
            int[] t = mesh.triangles();
            int[] surface = new int[t.length];
            for (int i = 0; i < t.length; i++) {
                surface[i] = first + t[i];
                tris.add(first + t[i]);
            }
            for (int i = 0; i < t.length / 3; i++) {
                triMaterial.add(material);
            }
            for (int h : mesh.hinges()) {
                hinges.add(first + h);
            }
            for (int i = 0; i < mesh.hinges().length / 4; i++) {
                hingeStiffness.add(material.bendingStiffness());
            }
            for (int i = 0; i < mesh.vertexCount(); i++) {
                contactVertices.add(first + i);
            }
            for (int e : mesh.edges()) {
                contactEdges.add(first + e);
            }
            for (int s : surface) {
                contactFaces.add(s);
            }
            halfThickness.add(material.thickness() / 2);
            selfContact.add(true);
            isCard.add(true);
            bodies.add(new SoftBody(name, SoftBody.Kind.CARD, first, mesh.vertexCount(), surface, material.thickness()));
            return this;
        }

        /** A fingertip: its boundary can touch other bodies; its bone nodes follow {@link BoneMotion}. */
        public Builder fingertip(String name, TetMesh mesh, SolidMaterial material, Placement at) {
            int first = addNodes(mesh.vertices(), at);
            for (int t : mesh.tets()) {
                tets.add(first + t);
            }
            for (int i = 0; i < mesh.tetCount(); i++) {
                tetMu.add(material.mu());
                tetLambda.add(material.lambda());
                tetDensity.add(material.density());
            }
            List<Integer> group = new ArrayList<>();
            for (int i = 0; i < mesh.vertexCount(); i++) {
                if (mesh.isBone(i)) {
                    bone.add(first + i);
                    group.add(first + i);
                }
            }
            boneGroups.add(group.stream().mapToInt(Integer::intValue).toArray());
            int[] s = mesh.surface();
            int[] surface = new int[s.length];
            TreeSet<Integer> verts = new TreeSet<>();
            TreeSet<Long> edges = new TreeSet<>();
            for (int i = 0; i < s.length; i++) {
                surface[i] = first + s[i];
                contactFaces.add(first + s[i]);
                verts.add(first + s[i]);
            }
            for (int f = 0; f < s.length / 3; f++) {
                for (int k = 0; k < 3; k++) {
                    int a = first + s[3 * f + k];
                    int b = first + s[3 * f + (k + 1) % 3];
                    edges.add(((long) Math.min(a, b) << 32) | Math.max(a, b));
                }
            }
            contactVertices.addAll(verts);
            for (long e : edges) {
                contactEdges.add((int) (e >>> 32));
                contactEdges.add((int) e);
            }
            halfThickness.add(0.0);
            selfContact.add(false);
            isCard.add(false);
            bodies.add(new SoftBody(name, SoftBody.Kind.FINGERTIP, first, mesh.vertexCount(), surface, 0));
            return this;
        }

        /**
         * Holds every node of the body {@code name} where the state puts it (Dirichlet nodes that
         * no bone moves): a card of a deck that lies still under what moves. Its elastic energy
         * is constant and left out; it still touches what moves.
         */
        public Builder fix(String name) {
            SoftBody body = bodies.stream().filter(x -> x.name().equals(name)).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("no body named " + name));
            for (int i = 0; i < body.nodeCount(); i++) {
                fixed.add(body.firstNode() + i);
            }
            return this;
        }

        /** A static ground plane z = height that every contact vertex touches. */
        public Builder ground(double height) {
            this.groundHeight = height;
            return this;
        }

        public SoftWorld build() {
            return new SoftWorld(this);
        }
    }

    /** Positions of one body's nodes from a state (a copy). */
    public double[] positions(SimState state, SoftBody body) {
        return Arrays.copyOfRange(state.x, 3 * body.firstNode(), 3 * (body.firstNode() + body.nodeCount()));
    }
}
