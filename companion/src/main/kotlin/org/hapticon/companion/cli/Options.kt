package org.hapticon.companion.cli

import org.hapticon.core.io.WavEncoding
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.RenderMode

/** Sample rate used when `--rate` is not given: CD audio, which every audio path plays. */
const val DEFAULT_SAMPLE_RATE: Int = 44_100

/** `--model` values. */
val MODEL_CHOICES: Map<String, EnvelopeModel> = linkedMapOf("paper" to EnvelopeModel.PAPER, "processing" to EnvelopeModel.PROCESSING)

/** `--mode` values. */
val MODE_CHOICES: Map<String, RenderMode> = linkedMapOf("exact" to RenderMode.EXACT, "fast" to RenderMode.FAST)

/** `--format` values. */
val FORMAT_CHOICES: Map<String, WavEncoding> = linkedMapOf("f32" to WavEncoding.FLOAT32, "s16" to WavEncoding.PCM16)

/** The command-line spelling of [model], e.g. `paper`. */
fun EnvelopeModel.cliName(): String = name.lowercase()

/** The command-line spelling of [encoding], e.g. `f32`. */
fun WavEncoding.cliName(): String = FORMAT_CHOICES.entries.first { it.value == this }.key
