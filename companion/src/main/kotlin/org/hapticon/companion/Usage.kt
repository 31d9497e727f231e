package org.hapticon.companion

/** The text `hapticon help` prints. */
val USAGE: String = """
    |hapticon - render, plot and benchmark haptic icons
    |
    |usage:
    |  hapticon icons
    |      Print the four presets (stroke, hit, knock, hug) as a JSON array of icon objects.
    |  hapticon render ICON --out FILE.wav [--rate HZ] [--format f32|s16]
    |                       [--model paper|processing] [--mode exact|fast]
    |      Render ICON to a mono WAV file, streaming block by block.
    |  hapticon plot ICON --out FILE.png [--model paper|processing] [--rate HZ]
    |      Draw ICON's envelope over its carrier waveform.
    |  hapticon bench [--json] [--quick]
    |      Measure render speed, FAST-mode error, first-block latency and allocation;
    |      --json prints one JSON object, --quick does fewer runs (a smoke test, not a measurement).
    |  hapticon demo --out DIR [--apk PATH]
    |      Render and plot the presets into DIR, plus envelope-models.png; report the APK if given.
    |  hapticon help
    |      Print this text.
    |
    |ICON is a preset name or the path of an icon JSON file, e.g.
    |  {"schema": "hapticon.icon", "version": 1, "name": "knock", "attack": 0.005, "sustain": 0.01,
    |   "level": 0.5, "release": 0.005, "note": 57, "period": 0.27, "count": 3}
    |Defaults: --rate $DEFAULT_SAMPLE_RATE, --format f32, --model paper, --mode exact.
    |
    |Exit status: 0 success; 2 usage or validation error (one line on stderr);
    |1 internal error (set HAPTICON_DEBUG=1 for the stack trace).
    |""".trimMargin()
