package handsim.cards.contact;

/**
 * A card simulation that went past a budget of its trial (memory for contacts, Newton
 * iterations, wall time): the trial is stopped and counted failed, with this message as the
 * reason, rather than exhausting the machine.
 */
public final class BudgetExceeded extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public BudgetExceeded(String message) {
        super(message);
    }
}
