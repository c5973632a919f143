/**
 * Small, dependency-free geometry for handsim: 3-vectors, unit quaternions, the cubic Hermite
 * curve of the paper's eq. (1), SLERP, and the little dense linear algebra that damped least
 * squares needs.
 *
 * <p>Conventions used everywhere in handsim: SI units, radians, right-handed world frame with
 * y up, quaternions stored as (w, x, y, z) and rotating vectors actively ({@code v' = q v q*}).
 */
package handsim.math;
