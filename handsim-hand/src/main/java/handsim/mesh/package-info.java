/**
 * Triangle meshes of the model's and the objects' shapes, built once for every consumer: the
 * viewer draws them ({@code handsim.viewer.SceneRenderer}) and the animation export writes them
 * ({@code handsim.export}), so what a user sees in handsim is what lands in their tool.
 * {@link handsim.mesh.ShapeMeshes} turns capsules, cylinders, boxes and spheres into
 * {@link handsim.mesh.TriangleMesh}es with outward normals and counter-clockwise front faces
 * (OpenGL's and glTF's convention), at a {@link handsim.mesh.Detail}; {@link handsim.mesh.Surface}
 * says which of the viewer's colours a body wears.
 *
 * <p>Imports {@code handsim.math} and {@code handsim.model} only: no OpenGL, no physics engine.
 */
package handsim.mesh;
