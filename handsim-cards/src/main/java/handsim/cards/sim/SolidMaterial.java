package handsim.cards.sim;

/** A volumetric material: density (kg/m³), Young's modulus (Pa) and Poisson's ratio. */
public record SolidMaterial(double density, double young, double poisson) {

    /** Lamé's μ (Pa). */
    public double mu() {
        return young / (2 * (1 + poisson));
    }

    /** Lamé's λ (Pa). */
    public double lambda() {
        return young * poisson / ((1 + poisson) * (1 - 2 * poisson));
    }
}
