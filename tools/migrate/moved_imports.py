#!/usr/bin/env python3
"""One-off for issue 10 (delete after the merge): fixes imports of the declarations that moved package.

    python3 tools/migrate/moved_imports.py app/src companion/src gesture/src sensor-bridge/src study/src

- app: the live session moved from org.hapticon.app.sensors to sensor-bridge (live/, protocol/,
  grains/, glove/); SensorHub became SensorSession.
- companion: the shared command-line pieces moved from org.hapticon.companion to .cli.
- synthetic people: org.hapticon.testing.gestures became org.hapticon.gesture.synthetic.
- ProtocolBenchmark moved to org.hapticon.companion.bench.
Not handled (by hand): companion's DecodeProtocol is gone (SensorProtocol.CLI_CHOICES; LUCID is LUCID_GLOVES;
`protocol.decoder(listener)` is `decoderFor(protocol, listener)`), and FramedEncoder.setGrains(params, …) is an
extension now (import org.hapticon.sensor.grains.setGrains outside that package).
Idempotent; prints each file it changed.
"""
import os
import re
import sys

MOVES = [
    ("org.hapticon.app.sensors", "org.hapticon.sensor.live", [
        "LiveFrame", "StreamInfo", "FrameListener", "PlotSource", "EmptyPlotSource", "ChannelHistory",
        "SensorDevice", "UsbDevices", "UsbAccessDeniedException", "ConnectionState", "StopCause",
        "StreamCounters", "StreamSnapshot", "symbol", "SensorSession", "CommandWriter"]),
    ("org.hapticon.app.sensors", "org.hapticon.sensor.protocol", ["SensorProtocol", "BAUD_RATES"]),
    ("org.hapticon.app.sensors", "org.hapticon.sensor.grains", [
        "GrainEngine", "GrainConfig", "GrainStatus", "ForceInput", "GrainSink"]),
    ("org.hapticon.app.sensors", "org.hapticon.sensor.glove", [
        "GloveSource", "GloveListener", "GloveChannels", "HubGloveSource", "ForceFeedbackStream",
        "ForceFeedbackSink", "PartnerHand", "NoPartner", "SimulatedPartner"]),
    ("org.hapticon.companion", "org.hapticon.companion.cli", [
        "Console", "Arguments", "UsageException", "OutputFiles", "WavExport", "AudioSettings", "IconSource",
        "DEFAULT_SAMPLE_RATE", "MODEL_CHOICES", "MODE_CHOICES", "FORMAT_CHOICES", "cliName", "renderable"]),
]
RENAMES = {
    r"\bSensorHub\b": "SensorSession",
    r"\borg\.hapticon\.testing\.gestures\b": "org.hapticon.gesture.synthetic",
    r"(?<!import )\borg\.hapticon\.companion\.Console\b": "org.hapticon.companion.cli.Console",  # written out in full
    r"\borg\.hapticon\.sensor\.protocol\.ProtocolBenchmark\b": "org.hapticon.companion.bench.ProtocolBenchmark",
}
# How a use looks in code; a plain name unless it is an extension function (called after a dot).
USE = {"cliName": r"\.cliName\(\)", "symbol": r"\.symbol\b"}


def use_pattern(name: str) -> str:
    return USE.get(name, rf"(?<![\w.]){name}\b")


def migrate(text: str) -> str:
    for pattern, replacement in RENAMES.items():
        text = re.sub(pattern, replacement, text)
    pkg = re.search(r"^package ([\w.]+)", text, re.M)
    own = pkg.group(1) if pkg else ""
    wanted = set()
    for old, new, names in MOVES:
        for name in names:
            line = f"import {old}.{name}\n"
            if line in text:
                text = text.replace(line, "")
                wanted.add((new, name))
            elif own == old and new != own:
                body = re.sub(r"^(package|import) .*$", "", text, flags=re.M)
                body = re.sub(r"//[^\n]*|/\*.*?\*/|\"(?:[^\"\\\n]|\\.)*\"", "", body, flags=re.S)
                if re.search(use_pattern(name), body):
                    wanted.add((new, name))
    wanted = {(p, n) for p, n in wanted if p != own and f"import {p}.{n}\n" not in text}
    if not wanted:
        return text
    lines = text.split("\n")
    imports = [i for i, l in enumerate(lines) if l.startswith("import ")]
    new_lines = sorted(f"import {p}.{n}" for p, n in wanted)
    if imports:
        lines[imports[0]:imports[0]] = new_lines
    else:
        at = next(i for i, l in enumerate(lines) if l.startswith("package ")) + 1
        lines[at:at] = [""] + new_lines
    return "\n".join(lines)


for root in sys.argv[1:]:
    for d, _, files in os.walk(root):
        for f in files:
            if f.endswith(".kt"):
                path = os.path.join(d, f)
                old = open(path, encoding="utf-8").read()
                new = migrate(old)
                if new != old:
                    open(path, "w", encoding="utf-8").write(new)
                    print(path)
