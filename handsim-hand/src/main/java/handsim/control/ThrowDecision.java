package handsim.control;

import java.util.Objects;

/**
 * What is decided when a THROW begins (sec. 3.7): the throw's seven parameters and how the catch
 * after it meets the object ({@code catching}; null: as the controller's config says).
 */
public record ThrowDecision(ThrowParameters throwing, CatchStyle catching) {

    public ThrowDecision {
        Objects.requireNonNull(throwing, "throwing");
    }

    /** {@code throwing}, its catch as the controller's config says. */
    public static ThrowDecision of(ThrowParameters throwing) {
        return new ThrowDecision(throwing, null);
    }
}
