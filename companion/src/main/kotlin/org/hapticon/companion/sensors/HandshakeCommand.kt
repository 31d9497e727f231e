package org.hapticon.companion.sensors

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.sensor.glove.HandshakeCsv

/**
 * `hapticon handshake --self ANGLES.csv --partner ANGLES.csv`: the self hand's per-region commands at each of
 * its time steps as [HandshakeCsv.format] CSV to stdout, one summary line to stderr.
 */
fun runHandshake(args: List<String>, console: Console) {
    val arguments = Arguments.parse("handshake", args, valueOptions = setOf("self", "partner"))
    arguments.requireNoPositionals()
    val selfPath = arguments.required("self")
    val partnerPath = arguments.required("partner")
    val selfCsv = InputFiles.readText("self", selfPath)
    val partnerCsv = InputFiles.readText("partner", partnerPath)
    val steps = InputFiles.sensorCsv { HandshakeCsv.commands(selfCsv, partnerCsv, selfPath, partnerPath) }
    console.out.print(HandshakeCsv.format(steps))
    console.err.println("handshake: ${steps.size} steps, active in ${steps.count { it.frame.active }}")
}
