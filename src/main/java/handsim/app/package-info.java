/** Command-line entry points ({@code scripts/handsim SUBCOMMAND}) that wire the other packages together. */
package handsim.app;
