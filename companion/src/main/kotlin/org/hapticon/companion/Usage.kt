package org.hapticon.companion

import org.hapticon.companion.cli.DEFAULT_SAMPLE_RATE

/** The text `hapticon help` prints. */
val USAGE: String = """
    |hapticon - render, plot and benchmark haptic icons
    |
    |usage:
    |  hapticon icons
    |      Print the four presets (stroke, hit, knock, hug) as a JSON array of icon objects.
    |  hapticon render ICON --out FILE.wav [--rate HZ] [--format f32|s16]
    |                       [--model paper|processing] [--mode exact|fast]
    |      Render ICON to a mono WAV file, streaming block by block. ICON may also be a pattern file
    |      (.ahap, .haptic, or a hapticon.pattern .json), rendered from its curves (docs/patterns.md).
    |  hapticon convert IN OUT [--range MIN_HZ:MAX_HZ] [--rate HZ] [--format f32|s16]
    |      Convert between a preset or icon/pattern .json, Apple .ahap and Meta .haptic (formats from the
    |      extensions; OUT may also be .wav). What the target format cannot keep is printed as notes on
    |      stderr. --range is the actuator's frequency range for sharpness and normalised frequency
    |      (default 65.4:523.3, MIDI notes 36-72).
    |  hapticon plot ICON --out FILE.png [--model paper|processing] [--rate HZ]
    |      Draw ICON's envelope over its carrier waveform.
    |  hapticon bench [--json] [--quick] [--messaging | --analysis | --grain [--runs N] [--interval-us N] [--spin-us N]
    |                 [--cpu-latency-us N] [--reader-nice N]]
    |      Measure render speed, FAST-mode error, first-block latency and allocation, and the sensor
    |      path: decoding speed, grain and handshake cost per sample, fake-port sample-to-grain latency
    |      through GrainEngine (p50/p99/max beside the re-created arithmetic, same run);
    |      --json prints one JSON object, --quick does fewer runs (a smoke test, not a measurement);
    |      --messaging measures message encode + decode and send-to-receive latency instead;
    |      --analysis times `analyze` on synthetic results of 10k, 100k and 1M rows (growth ratio, heap).
    |      --grain runs only the sample-to-grain latency, --runs times (3) with the load average beside
    |      each: p50/p99/max, run-queue wait, reader CPU; --interval-us paces samples (1000 = the board's
    |      1 kHz; default back to back), --spin-us keeps the reader spinning that long after each sample.
    |      Each grain over 1 ms is put down to its run-queue wait, a JVM safepoint, a GC or hypervisor steal
    |      on the reader's CPU (10 ms ticks), or counted unexplained. --cpu-latency-us N holds a PM QoS request
    |      on /dev/cpu_dma_latency for the runs (0..100000; root only, a refusal is one line and the runs go
    |      on); --reader-nice N (-20..19) renices the reader thread with `renice` before its first read.
    |  hapticon bench --broker-load [--users N[,N...]] [--duration S] [--interval MIN-MAX] [--burst K]
    |                 [--broker embedded|mosquitto|both] [--broker-heap-mb M] [--mosquitto-conf FILE] [--json]
    |      N simulated users (own password and client id, shipped ACL) on one broker, each sending a text
    |      with the knock icon to a random peer every MIN-MAX s (default 10-30) and answering with receipts;
    |      per broker and N: connections held, messages/s, p50/p99/max send-to-receive latency beside a
    |      2-user baseline, lost/duplicated counts, broker memory and CPU. Defaults: 100,1000 users, 60 s,
    |      both brokers (the embedded one in a child JVM; Mosquitto from companion/mosquitto, skipped with
    |      one line when not installed). --burst K: every user sends K at once at 1/3 and 2/3 of the run.
    |  hapticon demo --out DIR [--apk PATH]
    |      Render and plot the presets into DIR, plus envelope-models.png; report the APK if given.
    |      Also a sensor demo: a synthetic FSR press as a framed stream, decoded, and its grains; a handshake.
    |      And a chat: two users exchange a message with the knock icon through the embedded broker.
    |  hapticon decode --protocol csv|lucid|framed --in FILE
    |      Decode a recorded sensor byte stream: one JSON object per frame per line, then one line
    |      {"stats":{"frames":N,"bad_frames":N,"dropped_bytes":N,...}}. Garbage is counted, not an error.
    |  hapticon grains --in FSR.csv [--grains N] [--distribution linear|convex|concave]
    |      Compliance-grain onsets of an FSR recording (header time_s,force in N, or time_s,voltage in V)
    |      as CSV onset_s,bin,force_n: bin 0..N of N+1 (grains = bins - 1, so a full press fires N grains)
    |      and filtered force of each grain. Defaults: 24, linear.
    |  hapticon handshake --self ANGLES.csv --partner ANGLES.csv
    |      Tele-handshake commands for the self hand at each of its rows (header time_s,thumb_deg,middle_deg)
    |      as CSV time_s,active, then per region pressure V, actuator deg, servo (not palm), vibration amp.
    |  hapticon board ports
    |      The serial ports on this computer, one tab-separated line each: path (what --port takes), USB
    |      vvvv:pppp or -, description, serial number or -.
    |  hapticon board info --port DEV [--baud N]
    |      Ask a Hapticon framed board (hapticon_ref.ino) for its device info: name, firmware, ADC bits, rate,
    |      channels, and the raw force range its stand-alone grains span. --baud defaults to 115200.
    |  hapticon board set --port DEV --grains N [--shape SHAPE | --electrodes ROWS]
    |                    (--ma MA | --steps S | --calibration FILE)
    |                    [--distribution linear|convex|concave] [--range MIN:MAX] [--baud N]
    |      Send the board's grain parameters (SET_GRAINS) and print its answer in one line: acknowledged,
    |      refused with the firmware's reason, or no answer within 500 ms (exit 2 unless acknowledged).
    |      N grains per full press (0..99; bins = grains + 1). SHAPE: large_square (default), small_square,
    |      horizontal_line, vertical_line, triangle; or ROWS such as XXX/X.X/XXX (at least 4 electrodes).
    |      --ma: one current for all nine electrodes or nine comma-separated, in 0..2.7 mA (the hardware's
    |      next step up, 200 steps of 0.0135 mA); --steps: the same as steps 0..200; --calibration: the
    |      nine steps of a file saved by board calibrate --save (read strictly: a wrong schema or version,
    |      an unknown member, a step past 200 or an mA that is not its step's is refused, naming the file
    |      and the member). Past 2.7 mA, NaN or any other bad value is refused before the port is opened.
    |      The force range is the board's own (device info) unless --range gives it (a channel in physical
    |      units announces none).
    |  hapticon board calibrate --port DEV [--save FILE [--participant ID] [--force]] [--range MIN:MAX] [--baud N]
    |      Shaping Compliance's calibration on the terminal: each electrode alone, a 200 ms stimulus from
    |      0.8 mA (step 60, 0.81 mA); keys u/+/space one step up (not yet), d/- one step down (too strong),
    |      r again, y/Enter clear and pain-free (next electrode); then all nine with 39 grains while you
    |      press, until uniform: y/Enter done, d/- all one step down, 1-9 then w/s one electrode a step
    |      weaker/stronger. q stops. Never past 2.7 mA (step 200). Prints the
    |      calibrated steps for board set --steps; --save writes them (with their mA, the time and the
    |      participant) to FILE for board set --calibration: whole or not at all, nothing when stopped with
    |      q, and an existing FILE is refused before the port opens unless --force.
    |  hapticon chat --broker URL --user NAME --password-file FILE [--to PEER] [--wav-dir DIR] [--e2e [--keys-dir DIR]]
    |      Chat over MQTT (tcp://HOST:PORT, or ssl://HOST:PORT for TLS) with the app or another chat: lines
    |      are sent to PEER; /icon ICON [TEXT], /sticker NAME [TEXT], /to PEER, /help, /quit. Received icons
    |      are rendered to WAV files in DIR. Delivered and read receipts both ways. Says why it cannot
    |      connect; exits 2 when the broker refuses the user or typed lines never reached it.
    |      --anonymous instead of --password-file for a broker run with --allow-anonymous.
    |      --client-cert FILE.p12 --client-cert-password-file FILE instead: a client certificate (ssl:// only);
    |      --ca FILE trusts that CA (ca.crt of `broker ca init`) for the broker's certificate.
    |      --e2e encrypts and signs every message end to end (keys in ~/.hapticon/keys/NAME, peers' keys
    |      pinned on first contact): /safety PEER shows the safety number, /trust PEER accepts a changed key.
    |  hapticon broker [--port N] [--host ADDR] [--data DIR] [--users FILE] [--acl FILE] [--allow-anonymous]
    |                 [--tls-port N [--client-certs required|optional|none] [--ca-dir DIR]]
    |      Run the embedded MQTT broker until Ctrl-C (default 127.0.0.1:1883, files in ~/.hapticon/broker).
    |      Every client logs in with a user from the users file (Mosquitto's password-file format, created
    |      empty on first run) and is held to the ACL file (Mosquitto's format, the deployment's rules).
    |      --host binds a LAN address so phones can reach the laptop.
    |      --tls-port adds a TLS listener on --host (plain stays on 127.0.0.1) with the certificate of
    |      `broker ca init`; --client-certs: clients must (default), may or need not show a certificate.
    |  hapticon broker ca init [--data DIR | --ca-dir DIR] [--host NAME,...]
    |      Make the study's CA (ca.crt, ca.key mode 600) and the broker's certificate for those hosts.
    |  hapticon broker cert issue USER [--data DIR | --ca-dir DIR] [--out FILE] [--password-file FILE] [--days N]
    |      Write USER.p12 (mode 600): USER's client certificate (CN = USER, default 365 days) and key.
    |  hapticon broker adduser NAME [--data DIR | --users FILE] [--password-file FILE | --generate] [--iterations N]
    |      Add a broker user or change its password (asked on the terminal, the file's first line, or made up
    |      and printed once with --generate), stored with N PBKDF2 rounds (210000; 101 for Mosquitto).
    |  hapticon schedule --participants N --design paper|williams|full|random|fixed [--seed S] [--protocol FILE]
    |      Counterbalanced orders of a study (default: the originating study) as CSV participant,position,task,
    |      a blank line, then participant,task,position,stimulus; participant is the pseudonymous id (P000-A).
    |  hapticon compliance-schedule --participants N [--protocol ID] [--repetitions R] [--seed S]
    |      A compliance protocol's trials per participant as CSV participant,trial,condition,grains,shape,
    |      electrodes,repetition,before (before: calibrate, break+calibrate or nothing). ID: shaping-compliance
    |      (default: Task 1 as published, 9/19/39 grains x 4 shapes x 3 counterbalanced blocks, calibrated
    |      before each), shaping-compliance-shapes (Task 2, drawing) or shaping-compliance-extended (ours, 60).
    |  hapticon compliance-analysis ANSWERS.csv... [--out DIR]
    |      Shaping Compliance's analysis of the app's compliance answer files: Task 1 scores / SD per
    |      participant and repetition, reference rows at 0, ART ANOVA and ART-C (Tukey); Task 2's drawings as
    |      Figure 5's heatmaps (--out writes one PNG per shape).
    |  hapticon study-protocol [--out FILE]
    |      Print (or write) the default study protocol JSON, to edit and pass to --protocol. See docs/study.md.
    |  hapticon analyze RESULTS.csv [--out DIR] [--holm] [--test t|wilcoxon|both]
    |      Study statistics from a long-format results CSV (columns participant, task, icon, response):
    |      descriptives per task and icon, paired t and/or Wilcoxon signed-rank tests for every icon pair
    |      of a task (--holm adds Holm-adjusted p); Markdown to stdout, CSV/Markdown tables and one box
    |      plot per task into DIR (default ./analysis).
    |  hapticon collect [--port N] [--host H] [--db sqlite:PATH|postgresql://HOST/DB?user=..] [--allow-anonymous]
    |      Study collector: an HTTP service the app uploads results to (POST /v1/results, text/csv with
    |      X-Study-Id); GET /v1/studies/ID/results.csv, GET /health. Every /v1 request needs a bearer token
    |      of its study and role; --allow-anonymous turns that off (loudly). Defaults: 127.0.0.1:8080,
    |      sqlite:hapticon-results.db. Runs until Ctrl-C. Limits: --max-connections N (256),
    |      --idle-timeout-ms N (10000), --max-body-mb N (16), --rate N requests/s per client address (20)
    |      with --burst N (100); over the rate: 429.
    |  hapticon collect token add --study ID --role upload|download [--db DB]
    |  hapticon collect token list [--db DB]
    |  hapticon collect token revoke TOKEN_ID [--db DB]
    |      Collector tokens: add prints a new token once (only its SHA-256 is stored); an upload token
    |      cannot download, and a token of one study cannot touch another. See docs/security.md.
    |  hapticon classify-bench [--people N] [--seed S] [--out DIR] [--quick]
    |      Gesture recognition on simulated people, leave-one-participant-out: accuracy (mean ± SD), live
    |      decision latency (ms) and compute per window (µs) for windows 0.25-2 s × 10/30/100 trees, and a
    |      personal model from 5 takes per label; --out writes DIR/classify-bench.png. Defaults: 6 people, seed 1.
    |  hapticon train --in DIR_OR_CSV [MORE..] --out MODEL.json [--window S] [--trees N] [--seed S]
    |      Train a gesture model from labelled CSV (header time_s,<channels..>[,label]; without a label
    |      column the file name holds the label, e.g. p1-knock-gentle-3.csv). Defaults: 1 s, 30 trees.
    |  hapticon train --classifier logitboost --in DIR_OR_CSV [MORE..] --out MODEL.json [--iterations N]
    |      Social-touch model: one message per CSV named PERSON-LABEL[-N].csv, a skin recording (header
    |      time_s,joint,e:X:Y,..) or a pointer stream (header time_s,intensity,x,y,area); LogitBoost over
    |      decision stumps as WEKA runs it on the EIT-skin paper's 13 features (default 10 rounds); prints
    |      ten 10-fold CVs and leave-one-transmitter-out accuracy.
    |  hapticon classify --model MODEL.json --in REC.csv
    |      Classify a recording (same channels and rate as the model) live: CSV time_s,label,probability,event
    |      per decision, event 1 where a gesture is reported. With a social-touch model: label,probability
    |      of the one message in REC.csv.
    |  hapticon fit --in REC.wav|REC.csv [--channel NAME] [--envelope lowpass|rms]
    |               [--reference full-scale|peak|strongest|VALUE]
    |               [--name NAME] --out ICON.json [--json]
    |      Fit a haptic icon to a gesture recording (vibration WAV, or CSV time_s,<channel>..); write it as
    |      icon JSON and print the icon and its fit report (--json: one JSON object). See docs/gesture-extraction.md.
    |  hapticon fit-bench [--trials N] [--seed S]
    |      Parameter recovery of the fit on random synthetic icons at SNR 10-40 dB, per envelope method.
    |  hapticon replicate [ID] [--data DIR]
    |      Reproduce a published result and print ours beside the paper's figures; without ID, list them
    |      by seed-file number or short name: 000 haptic-icons, 001 eit-skin (social touch), 002 handshake|glove,
    |      003 shaping-compliance (electrotactile grains), 004 nao (touch gestures). `replicate nao --data DIR`
    |      scores the NAO study's recordings (PERSON-raw.csv, PERSON-indices.csv). docs/replication.md.
    |  hapticon help
    |      Print this text.
    |
    |ICON is a preset name or the path of an icon JSON file, e.g.
    |  {"schema": "hapticon.icon", "version": 1, "name": "knock", "attack": 0.005, "sustain": 0.01,
    |   "level": 0.5, "release": 0.005, "note": 57, "period": 0.27, "count": 3}
    |Defaults: --rate $DEFAULT_SAMPLE_RATE, --format f32, --model processing (what the study's participants felt;
    |paper = the trapezoid the paper describes), --mode exact.
    |
    |Exit status: 0 success; 2 usage or validation error (one line on stderr);
    |1 internal error (set HAPTICON_DEBUG=1 for the stack trace).
    |""".trimMargin()
