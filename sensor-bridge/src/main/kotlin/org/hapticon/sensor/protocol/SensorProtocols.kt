package org.hapticon.sensor.protocol

/**
 * The protocols a reader offers, in the order it lists them: the app's protocol choice and `hapticon decode
 * --protocol` read [DEFAULT]. Adding a protocol is one [SensorProtocol] implementation and one row there.
 * @throws IllegalArgumentException from the constructor when [entries] is empty or two share a label or CLI name.
 */
public class SensorProtocols(public val entries: List<SensorProtocol>) {
    init {
        require(entries.isNotEmpty()) { "a registry needs at least one protocol" }
        require(entries.map { it.cliName }.toSet().size == entries.size) { "two protocols share a CLI name: ${entries.map { it.cliName }}" }
        require(entries.map { it.label }.toSet().size == entries.size) { "two protocols share a label: ${entries.map { it.label }}" }
    }

    /** The protocols by [SensorProtocol.cliName], in [entries] order (the `--protocol` values). */
    public val cliChoices: Map<String, SensorProtocol> = entries.associateByTo(LinkedHashMap()) { it.cliName }

    /** This registry with [protocol] added last (e.g. a protocol of one's own board). */
    public operator fun plus(protocol: SensorProtocol): SensorProtocols = SensorProtocols(entries + protocol)

    public companion object {
        /** Every protocol Hapticon reads: one row per protocol. */
        public val DEFAULT: SensorProtocols = SensorProtocols(
            listOf(
                CsvProtocol,
                LucidGlovesProtocol,
                FramedBinaryProtocol,
            ),
        )
    }
}
