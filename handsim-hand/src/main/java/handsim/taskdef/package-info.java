/**
 * The tasks as definitions: each task (height, box, flip) is one {@link
 * handsim.taskdef.TaskDefinition} built once from its resolved configs/tasks file, which makes
 * its tasks ({@code handsim.task}), checks the evaluate options it takes and builds its
 * evaluation ({@code handsim.evaluation}), and gives a scene its goal to draw and steer. {@link
 * handsim.taskdef.TaskDefinitions} is the one registry of task names.
 *
 * <p>Imports {@code handsim.math}, {@code handsim.config}, {@code handsim.task} and {@code
 * handsim.evaluation}; never an engine, DL4J, LWJGL or the app.
 */
package handsim.taskdef;
