/**
 * Reading handsim's JSON files (the model in {@code models/}, everything tunable in
 * {@code configs/}) with errors that name the file, the field and the bad value, and applying
 * {@code --set key=value} overrides before anything is parsed.
 *
 * <p>Imports {@code handsim.math} and Jackson.
 */
package handsim.config;
