/**
 * Taking the animation out: a run's motion as glTF 2.0 ({@code .glb}, or {@code .gltf} with a
 * {@code .bin}) and BVH. A {@link handsim.export.MotionRecorder} samples the
 * {@link handsim.sim.WorldSnapshot}s a watcher already has (the viewer's frames, a headless
 * run's ticks) at a fixed rate into a {@link handsim.export.MotionClip}; an
 * {@link handsim.export.ExportTarget} writes it atomically: {@link handsim.export.GltfWriter}
 * as the model's body hierarchy with the meshes of {@link handsim.mesh.ShapeMeshes} and
 * translation and rotation channels, {@link handsim.export.BvhWriter} as a skeleton with the
 * model's Euler channels. The simulation never knows: nothing here steps or changes it.
 *
 * <p>Imports {@code handsim.math}, {@code handsim.model}, {@code handsim.kin},
 * {@code handsim.mesh}, {@code handsim.sim} (snapshots and object specs only),
 * {@code handsim.task.Goal} (what the goal looks like), {@code handsim.report} (its files are
 * written through {@code Outputs}) and Jackson (glTF's JSON); no OpenGL,
 * no physics engine.
 */
package handsim.export;
