package org.hapticon.companion.bench

import org.hapticon.companion.sensors.SensorDemo
import org.hapticon.companion.sensors.SyntheticPress
import org.hapticon.sensor.grains.FsrForceConverter
import org.hapticon.sensor.grains.GrainConfig
import org.hapticon.sensor.grains.GrainEngine
import org.hapticon.sensor.grains.GrainDecider
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.sensor.grains.GrainSink
import org.hapticon.sensor.protocol.FrameListener
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.live.liveDecoderFor
import org.hapticon.sensor.port.SensorReader
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.safety.SafetyLimits
import java.io.File
import java.lang.management.ManagementFactory
import java.nio.ByteBuffer
import java.nio.channels.FileChannel
import java.nio.file.Path
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.locks.LockSupport
import kotlin.math.ceil

/**
 * Latency from an FSR sample arriving to the grain command it causes: [p50Micros] and [p99Micros] (nearest
 * rank) and [maxMicros] over the [grains] measured, which [samples] samples (after warm-up) caused.
 * [handlerBytesPerSample]: bytes allocated per measured sample from the decoded frame to the command
 * encoded (force, decision, encoding); [readerBytesPerSample]: the reader thread's whole allocation per
 * sample, which adds decoding (0, measured by the decoding bench) and the [BenchSerialLine]'s own work (a
 * lock condition node per wait, a recorded copy per write: the bench's line, not the app's). NaN where
 * not counted.
 *
 * Where the worst case comes from, measured in the same run (Linux; NaN or 0 elsewhere): for each grain the
 * time the reader thread spent runnable but waiting for a CPU (the kernel's run-queue wait,
 * `/proc/<pid>/task/<tid>/schedstat` field 2) and whether a garbage collection ran. [runQueueMicrosAtMax] and
 * [gcAtMax] describe the worst grain; [maxWithoutRunQueueMicros] is the worst grain once each grain's own
 * run-queue wait is taken off — what a machine with a free core would show; [over1ms] grains took longer
 * than 1 ms, of which [over1msByRunQueue] are under 1 ms without their run-queue wait and [over1msWithGc] saw
 * a collection.
 *
 * What the reader costs in CPU (Linux, schedstat field 1, NaN elsewhere): [readerCpuMicrosPerSample], its
 * running time per measured sample, and [readerCpuShare], that time over the measured wall time (1.0 = one
 * core kept busy), which shows what a spinning reader burns.
 *
 * Every grain over 1 ms, by cause ([SlowGrainCauses.of]; a grain may have several): [over1msByRunQueue],
 * [over1msWithGc], [over1msBySafepoint] (its time inside a JVM safepoint, from HotSpot's safepoint log),
 * [over1msBySteal] (hypervisor steal on the reader's CPU near it, /proc/stat's 10 ms ticks),
 * [over1msByWaitAndSafepoint] (the two together, neither alone) and [over1msUnexplained]. [safepoints] ran
 * during the measured samples (-1: no log), the longest [longestSafepointMicros] (the VM operation
 * [longestSafepoint]); [safepointMicrosAtMax] and
 * [stealTicksAtMax] are the worst grain's (-1: unknown, or the worst grain was not over 1 ms for steal);
 * [stealShare] is steal over all CPUs' time during the measured samples (NaN off Linux).
 */
data class GrainLatencyResult(
    val samples: Int,
    val grains: Int,
    val p50Micros: Double,
    val p99Micros: Double,
    val maxMicros: Double,
    val handlerBytesPerSample: Double = Double.NaN,
    val readerBytesPerSample: Double = Double.NaN,
    val runQueueMicrosAtMax: Double = Double.NaN,
    val gcAtMax: Boolean = false,
    val maxWithoutRunQueueMicros: Double = Double.NaN,
    val over1ms: Int = 0,
    val over1msByRunQueue: Int = 0,
    val over1msWithGc: Int = 0,
    val readerCpuMicrosPerSample: Double = Double.NaN,
    val readerCpuShare: Double = Double.NaN,
    val over1msBySafepoint: Int = 0,
    val over1msBySteal: Int = 0,
    val over1msByWaitAndSafepoint: Int = 0,
    val over1msUnexplained: Int = 0,
    val safepoints: Int = -1,
    val longestSafepointMicros: Double = Double.NaN,
    val longestSafepoint: String = "",
    val safepointMicrosAtMax: Double = Double.NaN,
    val stealTicksAtMax: Long = -1L,
    val stealShare: Double = Double.NaN,
)

/**
 * Measures the app's grain path end to end on a [BenchSerialLine]: the bench thread writes one framed FSR
 * sample ([SyntheticPress], 1 kHz, 12 bit) into the port; a [SensorReader] thread reads and decodes it, and
 * [route] turns it into a grain decision; when a grain starts a set-outputs command (output 0 at full scale) is
 * encoded and written back to the port. Each latency runs from just before the sample's write to just after
 * the command's write (System.nanoTime on both threads).
 *
 * One sample is in flight at a time: the next is written only once the reader has handled the previous one,
 * so a latency never includes queueing behind earlier samples, only the wake-up and the work. The first
 * [warmupSamples] are not counted, so the JIT has compiled the path.
 *
 * The bench thread waits for each answer parked (the reader unparks it after recording the latency), not
 * spinning: on 2 cores a spinning bench thread holds one of them while the reader needs one (on the
 * phone no CPU thread writes the samples). [intervalMicros] > 0 paces the samples at that period (1000 = the board's 1 kHz), so
 * the reader parks between samples as on the phone; 0 writes each sample as soon as the last was handled.
 * [readerSpinMicros] > 0 keeps the reader warm: after each read that delivered bytes it spins that long
 * ([Thread.onSpinWait]) watching for the next sample before it blocks in the port's read — the experiment
 * behind the choice in docs/performance.md, not something the app's USB port can do (Android's bulk
 * transfer cannot poll).
 *
 * [readerSetup] runs on the reader thread before its first read (the [SensorReader]'s `threadSetup`, as the app
 * raises its reader's priority there) with the thread's Linux id (-1 where there is no /proc/thread-self).
 *
 * Slow grains (over 1 ms) are attributed without touching the reader's path: HotSpot's safepoint log is on for
 * the run ([SafepointLogging]); the bench thread reads `/proc/stat` (per-CPU steal) at the run's start and end,
 * at most every 10 ms between samples, and after each slow grain, with the reader's CPU (its stat's field 39):
 * the steal counter's move from the last reading before the grain to the one after it. All of it between
 * samples, into preallocated arrays.
 */
class GrainLatency(
    private val samples: Int,
    private val warmupSamples: Int,
    private val route: Route = Route.ENGINE,
    private val intervalMicros: Int = 0,
    private val readerSpinMicros: Int = 0,
    private val readerSetup: (tid: Long) -> Unit = {},
) {
    /** What runs between the decoded frame and the command. */
    enum class Route(val label: String) {
        /**
         * The shipped path: sensor-bridge's live decoding into a [LiveFrame], then the app's [GrainEngine]
         * itself (FSR counts from the channel's unit, 12-bit from the device info, default [GrainSettings],
         * burst at 255), whose [GrainSink] encodes the command.
         */
        ENGINE("GrainEngine"),

        /** The baseline: the engine's arithmetic re-created by hand (force, [GrainDecider], encoding) on the decoded [SampleFrame]. */
        ARITHMETIC("re-created arithmetic"),
    }

    init {
        require(samples >= 1 && warmupSamples >= 0) { "need samples >= 1 and warmupSamples >= 0, were $samples and $warmupSamples" }
        require(intervalMicros in 0..1_000_000 && readerSpinMicros in 0..1_000_000) { "intervalMicros and readerSpinMicros must be in 0..1000000, were $intervalMicros and $readerSpinMicros" }
    }

    /** Runs the measurement; throws [IllegalStateException] if the reader fails, stalls, or no grain fires. */
    fun run(): GrainLatencyResult {
        val total = warmupSamples + samples
        val frames = encodeFrames(total)
        val writtenAt = LongArray(total)
        val latencies = LongArray(total) { NOT_A_GRAIN }
        // The reader's run-queue wait (ns, cumulative) and the JVM's collection count after each sample; read by
        // this thread between samples, so outside every latency, into preallocated arrays (nothing allocated).
        val waitedAfter = LongArray(total) { -1L }
        val ranAfter = LongArray(total) { -1L }
        val collectionsAfter = LongArray(total)
        val collectors = ManagementFactory.getGarbageCollectorMXBeans()
        val runQueue = ByteBuffer.allocateDirect(RUN_QUEUE_BYTES)
        var schedstat: FileChannel? = null
        val handled = AtomicInteger(0)
        val port = WarmPort(BenchSerialLine(), readerSpinMicros * 1_000L)
        val waiter = Thread.currentThread()
        val wiring = PathWiring(port, writtenAt, latencies, handled, warmupSamples, total, waiter)
        val side = when (route) {
            Route.ENGINE -> EnginePath(wiring)
            Route.ARITHMETIC -> ArithmeticPath(wiring)
        }
        var failure: Throwable? = null
        val decoder = when (side) {
            is EnginePath -> liveDecoderFor(SensorProtocol.FRAMED, side)
            is ArithmeticPath -> FramedDecoder(side)
        }
        val reader = SensorReader(port, decoder, { _, cause -> failure = cause }, bufferSize = READ_BYTES, threadSetup = {
            // Before the first read: this thread's /proc directory ("/proc/PID/task/TID"), then the caller's set-up.
            val task = runCatching { File("/proc/thread-self").canonicalPath }.getOrNull()
            side.taskDir = task
            side.schedstat = task?.let { "$it/schedstat" }
            readerSetup(task?.substringAfterLast('/')?.toLongOrNull() ?: -1L)
        })
        // Slow-grain attribution: steal per CPU before and after each slow grain, the reader's CPU, the safepoints.
        val steal = StealReader()
        val slow = IntArray(MAX_SLOW_GRAINS)
        val slowStealTicks = LongArray(MAX_SLOW_GRAINS) { -1L }
        var slowCount = 0
        var taskStat: FileChannel? = null
        val safepointLog = SafepointLogging.start()
        steal.read()
        reader.start("hapticon-bench-grain-latency")
        var measuredFrom = 0L
        var measuredTo = 0L
        try {
            port.enqueue(frames.deviceInfo)
            var due = System.nanoTime()
            for (i in 0 until total) {
                if (intervalMicros > 0) {
                    // Paced: the next sample is due one period after the last was due, as a board's clock sends them.
                    due += intervalMicros * 1_000L
                    while (System.nanoTime() < due) LockSupport.parkNanos(due - System.nanoTime())
                }
                if (i == warmupSamples) {
                    steal.markRunStart()
                    measuredFrom = System.nanoTime()
                }
                writtenAt[i] = System.nanoTime()
                port.enqueue(frames.samples[i])
                awaitHandled(handled, i + 1, reader) { failure }
                if (schedstat == null) schedstat = side.schedstat?.let { openOrNull(it) }
                if (schedstat != null && schedstatNanos(schedstat!!, runQueue)) {
                    ranAfter[i] = runQueue.getLong(RAN_AT)
                    waitedAfter[i] = runQueue.getLong(WAITED_AT)
                }
                collectionsAfter[i] = collectors.sumOf { it.collectionCount }
                // After the latency was taken: a slow grain gets the steal on the reader's CPU since the last reading.
                if (taskStat == null) taskStat = side.taskDir?.let { openOrNull("$it/stat") }
                if (i >= warmupSamples && latencies[i] > ONE_MS_NANOS && slowCount < MAX_SLOW_GRAINS) {
                    val cpu = taskStat?.let { steal.cpuOf(it) } ?: -1
                    slow[slowCount] = i
                    slowStealTicks[slowCount++] = steal.movedSince(cpu)
                } else if (System.nanoTime() - steal.readAt >= STEAL_REFRESH_NANOS) {
                    steal.read()
                }
            }
            measuredTo = System.nanoTime()
            steal.markRunEnd()
        } finally {
            taskStat?.close()
            safepointLog?.close()
            schedstat?.close()
            reader.stop()
            port.close()
            reader.awaitStop(STALL_MILLIS)
        }
        val grainIndices = (warmupSamples until total).filter { latencies[it] != NOT_A_GRAIN }
        check(grainIndices.isNotEmpty()) { "no grain fired in $samples samples" }
        val measured = grainIndices.map { latencies[it] }.sorted()
        // Per grain: the reader's run-queue wait during it (NaN when unknown) and whether a collection ran.
        val waited = grainIndices.associateWith { i ->
            if (i == 0 || waitedAfter[i] < 0 || waitedAfter[i - 1] < 0) Double.NaN else (waitedAfter[i] - waitedAfter[i - 1]).toDouble()
        }
        val collected = grainIndices.associateWith { i -> i > 0 && collectionsAfter[i] != collectionsAfter[i - 1] }
        val worst = grainIndices.maxBy { latencies[it] }
        // The reader's running time over the measured samples (from the end of the last warm-up sample).
        val ranFrom = if (warmupSamples > 0) ranAfter[warmupSamples - 1] else -1L
        val ran = if (ranFrom < 0 || ranAfter[total - 1] < 0) Double.NaN else (ranAfter[total - 1] - ranFrom).toDouble()
        val over = grainIndices.filter { latencies[it] > ONE_MS_NANOS }
        val safepoints = safepointLog?.finish()?.filter { it.endNanos > measuredFrom && it.startNanos < measuredTo }
        fun safepointNanos(i: Int): Long = safepoints?.let { SafepointLog.overlapNanos(it, writtenAt[i], writtenAt[i] + latencies[i]) } ?: -1L
        val stealOf = (0 until slowCount).associate { slow[it] to slowStealTicks[it] }
        val causes = SlowGrainCauses.of(
            over.map { i -> SlowGrain(latencies[i], waited.getValue(i), collected.getValue(i), safepointNanos(i), stealOf[i] ?: -1L) },
            ONE_MS_NANOS,
        )
        return GrainLatencyResult(
            samples, measured.size, rank(measured, 0.50) / 1e3, rank(measured, 0.99) / 1e3, measured.last() / 1e3,
            handlerBytesPerSample = side.handlerBytes() / samples,
            readerBytesPerSample = side.allocatedBytes() / samples,
            runQueueMicrosAtMax = waited.getValue(worst) / 1e3,
            gcAtMax = collected.getValue(worst),
            maxWithoutRunQueueMicros = grainIndices.maxOf { latencies[it] - waited.getValue(it) } / 1e3,
            over1ms = over.size,
            over1msByRunQueue = causes.runQueue,
            over1msWithGc = causes.gc,
            readerCpuMicrosPerSample = ran / 1e3 / samples,
            readerCpuShare = ran / (measuredTo - measuredFrom).coerceAtLeast(1L),
            over1msBySafepoint = causes.safepoint,
            over1msBySteal = causes.steal,
            over1msByWaitAndSafepoint = causes.waitAndSafepoint,
            over1msUnexplained = causes.unexplained,
            safepoints = safepoints?.size ?: -1,
            longestSafepointMicros = safepoints?.maxOfOrNull { it.endNanos - it.startNanos }?.div(1e3) ?: Double.NaN,
            longestSafepoint = safepoints?.maxByOrNull { it.endNanos - it.startNanos }?.operation.orEmpty(),
            safepointMicrosAtMax = if (safepoints == null) Double.NaN else safepointNanos(worst) / 1e3,
            stealTicksAtMax = stealOf[worst] ?: -1L,
            stealShare = steal.runShare(),
        )
    }

    /**
     * The reader side's bookkeeping, shared by both paths: per sample, the bytes allocated from the decoded
     * frame to the command encoded ([measure]), then the command's write and its latency.
     */
    private sealed class GrainPath(
        val port: WarmPort,
        val writtenAt: LongArray,
        val latencies: LongArray,
        val handled: AtomicInteger,
        val warmupSamples: Int,
        val total: Int,
        private val waiter: Thread,
    ) {
        constructor(w: PathWiring) : this(w.port, w.writtenAt, w.latencies, w.handled, w.warmupSamples, w.total, w.waiter)

        private val threads = ManagementFactory.getThreadMXBean() as com.sun.management.ThreadMXBean
        private val counting = threads.isThreadAllocatedMemorySupported && threads.isThreadAllocatedMemoryEnabled

        // Read only by the bench thread after handled reaches total (published by that volatile write).
        var bytesAtWarmupEnd = 0L
        var bytesAtEnd = 0L
        var handlerBytesSum = 0L

        /** Bytes allocated from decoded frame to command encoded over the measured samples; NaN if not counted. */
        fun handlerBytes(): Double = if (counting) handlerBytesSum.toDouble() else Double.NaN

        /** Bytes this reader thread allocated from the first measured sample to the end; NaN if not counted. */
        fun allocatedBytes(): Double = if (counting) (bytesAtEnd - bytesAtWarmupEnd).toDouble() else Double.NaN

        fun threadBytes(): Long = if (counting) threads.getThreadAllocatedBytes(Thread.currentThread().id) else 0L

        val encoder = FramedEncoder()
        val command = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val fullScale = intArrayOf(SafetyLimits.SERVO_MAX)
        var index = 0

        /** This reader thread's schedstat file and /proc directory (Linux), found before its first read; null elsewhere. */
        @Volatile var schedstat: String? = null
        @Volatile var taskDir: String? = null

        /** Called once per decoded sample on the reader thread: [decide] returns the command's length, 0 for no grain. */
        inline fun measure(decide: () -> Int) {
            val i = index++
            val entered = threadBytes()
            if (i == warmupSamples) bytesAtWarmupEnd = entered
            val length = decide()
            // Counted up to the command encoded: the port write is the BenchSerialLine's (it records a copy).
            if (i >= warmupSamples) handlerBytesSum += threadBytes() - entered
            if (length > 0) {
                port.write(command, 0, length, WRITE_TIMEOUT_MILLIS)
                latencies[i] = System.nanoTime() - writtenAt[i]
            }
            val left = threadBytes()
            if (i == total - 1) bytesAtEnd = left
            // The volatile write publishes latencies[i] (and the byte counts) to the bench thread, then wakes it:
            // after the latency was taken, so its wake-up is not on the figure.
            handled.set(i + 1)
            LockSupport.unpark(waiter)
        }
    }

    /** What the bench hands either path, as one value so that the two paths' constructors do not repeat the list. */
    private class PathWiring(
        val port: WarmPort, val writtenAt: LongArray, val latencies: LongArray, val handled: AtomicInteger,
        val warmupSamples: Int, val total: Int, val waiter: Thread,
    )

    /** The shipped path: the decoded [LiveFrame] goes to a real [GrainEngine], whose sink encodes the command. */
    private class EnginePath(wiring: PathWiring) : GrainPath(wiring), FrameListener {
        private var length = 0

        // The engine calls the sink on this (the reader) thread, at most once per frame.
        private val engine = GrainEngine { length = encoder.setOutputs(0, fullScale, command) }.apply {
            // The board's rate as the fallback: configured before the stream, as when a user enables the mode first.
            configure(GrainConfig(channel = 0, settings = GrainSettings(), amplitude = 255, fallbackSampleRateHz = SyntheticPress.SAMPLE_RATE_HZ.toDouble()))
        }

        override fun onFrame(frame: LiveFrame, info: StreamInfo) = measure {
            length = 0
            engine.onFrame(frame, info)
            length
        }
    }

    /** The baseline: the engine's arithmetic re-created on the decoded [SampleFrame] (what the grain path costs without the engine's own lock-free run). */
    private class ArithmeticPath(wiring: PathWiring) : GrainPath(wiring), FramedDecoder.Listener {
        private val converter = FsrForceConverter()
        private val decider = GrainDecider(GrainSettings(), SyntheticPress.SAMPLE_RATE_HZ.toDouble())

        override fun onSample(frame: SampleFrame) = measure {
            // The allocation-free conversion, as GrainEngine uses (NaN, a fault, never fires).
            if (decider.offer(converter.newtonsOrNaN(SyntheticPress.voltsOfCounts(frame.values[0])))) encoder.setOutputs(0, fullScale, command) else 0
        }
    }

    /** Each frame encoded beforehand, so a write times only the port. */
    private class Frames(val deviceInfo: ByteArray, val samples: List<ByteArray>)

    private fun encodeFrames(total: Int): Frames {
        val encoder = FramedEncoder()
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val deviceInfo = buffer.copyOf(encoder.deviceInfo(SensorDemo.DEVICE, buffer))
        val value = IntArray(1)
        val samples = List(total) { k ->
            value[0] = SyntheticPress.countsAt(k)
            buffer.copyOf(encoder.sample(k * 1_000_000L / SyntheticPress.SAMPLE_RATE_HZ, value, buffer))
        }
        return Frames(deviceInfo, samples)
    }

    /**
     * Parks until [handled] reaches [count] (the reader unparks this thread); the reader answers within
     * microseconds, so a stall is a failure. Parked, not spinning: a spinning waiter would hold one of the
     * machine's cores while the reader needs one.
     */
    private inline fun awaitHandled(handled: AtomicInteger, count: Int, reader: SensorReader, failure: () -> Throwable?) {
        val deadline = System.nanoTime() + STALL_MILLIS * 1_000_000
        while (handled.get() < count) {
            if (!reader.isRunning) throw IllegalStateException("the sensor reader stopped at sample $count", failure())
            val left = deadline - System.nanoTime()
            check(left > 0) { "sample $count was not handled within $STALL_MILLIS ms" }
            LockSupport.parkNanos(this, minOf(left, PARK_SLICE_NANOS))
        }
    }

    /**
     * The [BenchSerialLine] as the reader sees it, optionally kept warm: after a read that delivered bytes, the
     * next read first spins up to [spinNanos] watching for a sample the bench has enqueued since ([enqueued], a
     * volatile count), so one that arrives within the window is read without the reader ever parking. With 0
     * it is the plain port: the reader blocks in the port's read and is woken by each sample.
     */
    private class WarmPort(private val line: BenchSerialLine, private val spinNanos: Long) : org.hapticon.sensor.port.SerialPort by line {
        @Volatile private var enqueued = 0L
        private var consumed = 0L
        private var delivered = false

        /** Enqueues [bytes] as one read and counts it. */
        fun enqueue(bytes: ByteArray) {
            line.send(bytes)
            enqueued++
        }

        override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
            if (spinNanos > 0 && delivered) {
                val until = System.nanoTime() + spinNanos
                while (enqueued == consumed && System.nanoTime() < until) Thread.onSpinWait()
            }
            val n = line.read(buffer, offset, length, timeoutMillis)
            delivered = n > 0
            if (delivered) consumed = enqueued.coerceAtMost(consumed + 1)
            return n
        }
    }

    /**
     * `/proc/stat` read into preallocated buffers ([ProcStat.parse]): [read] keeps the newest per-CPU steal and
     * [readAt] its time; [movedSince] reads again and gives a CPU's steal ticks since the reading before; the run's
     * first and last readings give [runShare]. Nothing is allocated per reading; unreadable (off Linux) it says -1/NaN.
     */
    private class StealReader {
        private val channel: FileChannel? = runCatching { FileChannel.open(Path.of("/proc/stat")) }.getOrNull()
        private val bytes = ByteArray(PROC_STAT_BYTES)
        private val buffer = ByteBuffer.wrap(bytes)
        private val aggregate = LongArray(ProcStat.CPU_FIELDS)
        private var steal = LongArray(MAX_CPUS) { -1L }
        private var before = LongArray(MAX_CPUS) { -1L }
        private val atStart = LongArray(ProcStat.CPU_FIELDS)
        private val atEnd = LongArray(ProcStat.CPU_FIELDS)
        private val taskBytes = ByteArray(TASK_STAT_BYTES)
        private val taskBuffer = ByteBuffer.wrap(taskBytes)
        private var ok = false
        var readAt = 0L
            private set

        fun read(): Boolean {
            val c = channel ?: return false
            buffer.clear()
            var n = 0
            while (buffer.hasRemaining()) {
                val r = c.read(buffer, n.toLong())
                if (r <= 0) break
                n += r
            }
            readAt = System.nanoTime()
            ok = ProcStat.parse(bytes, n, aggregate, steal) > 0
            return ok
        }

        /** The CPU the task whose stat [task] is last ran on, or -1. */
        fun cpuOf(task: FileChannel): Int {
            taskBuffer.clear()
            val n = runCatching { task.read(taskBuffer, 0) }.getOrDefault(-1)
            return if (n <= 0) -1 else ProcStat.processor(taskBytes, n)
        }

        /** Steal ticks of [cpu] from the previous reading to a new one (-1 unknown); the new one becomes the previous. */
        fun movedSince(cpu: Int): Long {
            val swap = before
            before = steal
            steal = swap
            if (!ok) return -1L.also { read() }
            val moved = if (read() && cpu in 0 until MAX_CPUS && before[cpu] >= 0 && steal[cpu] >= 0) steal[cpu] - before[cpu] else -1L
            return moved
        }

        fun markRunStart() { if (read()) aggregate.copyInto(atStart) else atStart.fill(-1L) }

        fun markRunEnd() { if (read()) aggregate.copyInto(atEnd) else atEnd.fill(-1L) }

        /** Steal over all CPUs' time between [markRunStart] and [markRunEnd] (0..1), NaN if unread. */
        fun runShare(): Double {
            if (atStart[0] < 0 || atEnd[0] < 0) return Double.NaN
            var total = 0L
            for (k in 0 until ProcStat.CPU_FIELDS) if (k != GUEST && k != GUEST_NICE) total += atEnd[k] - atStart[k]
            return if (total <= 0) Double.NaN else (atEnd[ProcStat.STEAL] - atStart[ProcStat.STEAL]).toDouble() / total
        }

        private companion object {
            const val PROC_STAT_BYTES = 65_536
            const val TASK_STAT_BYTES = 1_024
            const val MAX_CPUS = 1_024
            // Guest time is already counted in user and nice (proc(5)).
            const val GUEST = 8
            const val GUEST_NICE = 9
        }
    }

    private fun openOrNull(path: String): FileChannel? = runCatching { FileChannel.open(Path.of(path)) }.getOrNull()

    /**
     * Reads a schedstat file ("run ns, run-queue wait ns, slices") again from offset 0 into [buffer] and, on
     * success, leaves fields 1 and 2 as longs at [RAN_AT] and [WAITED_AT] of it (past the text; no allocation).
     */
    private fun schedstatNanos(channel: FileChannel, buffer: ByteBuffer): Boolean {
        buffer.clear().limit(TEXT_BYTES)
        val read = channel.read(buffer, 0)
        if (read <= 0) return false
        // Absolute puts are bounded by the limit: open the whole buffer again for the two longs.
        buffer.limit(buffer.capacity())
        var field = 0
        var value = 0L
        for (k in 0 until read) {
            val c = buffer.get(k).toInt()
            when {
                c == ' '.code -> {
                    if (field == 0) buffer.putLong(RAN_AT, value) else { buffer.putLong(WAITED_AT, value); return true }
                    field++
                    value = 0L
                }
                c in '0'.code..'9'.code -> value = value * 10 + (c - '0'.code)
                else -> return false
            }
        }
        return false
    }

    private fun rank(sorted: List<Long>, fraction: Double): Double = sorted[(ceil(fraction * sorted.size).toInt() - 1).coerceAtLeast(0)].toDouble()

    private companion object {
        const val NOT_A_GRAIN = -1L
        const val READ_BYTES = 256
        const val WRITE_TIMEOUT_MILLIS = 100
        const val STALL_MILLIS = 5_000L
        const val TEXT_BYTES = 112
        const val RAN_AT = 112
        const val WAITED_AT = 120
        const val RUN_QUEUE_BYTES = 128
        const val PARK_SLICE_NANOS = 10_000_000L
        const val ONE_MS_NANOS = 1_000_000L
        const val MAX_SLOW_GRAINS = 4_096
        const val STEAL_REFRESH_NANOS = 10_000_000L
    }
}
