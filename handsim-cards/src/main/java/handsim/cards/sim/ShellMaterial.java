package handsim.cards.sim;

/**
 * A thin-shell material: density (kg/m³), Young's modulus (Pa), Poisson's ratio and thickness (m).
 */
public record ShellMaterial(double density, double young, double poisson, double thickness) {

    /** Hinge bending stiffness k = E t³ / (24 (1 − ν²)) (J). */
    public double bendingStiffness() {
        return young * thickness * thickness * thickness / (24 * (1 - poisson * poisson));
    }
}
