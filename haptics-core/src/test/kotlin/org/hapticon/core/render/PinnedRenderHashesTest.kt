package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.onOffWaveform
import org.hapticon.core.pattern.signal
import org.hapticon.core.pattern.toPattern
import org.hapticon.core.pattern.vibrationWaveform
import org.junit.Assert.assertEquals
import org.junit.Test
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.security.MessageDigest

/**
 * Every output the renderers make, pinned bit for bit: a SHA-256 per icon and output over the little-endian
 * bytes of every sample (float, double, PCM16), every vibrator entry, control point and pattern key, and every
 * fidelity figure, for both envelope models, both carrier modes and the rates the app and the study use. A
 * refactor of the envelope or the render engine must leave each hash as it is; a deliberate change of output
 * changes the hash, and the new value is written here with the reason in the commit.
 *
 * The icons are the four presets and the extremes: a zero-length icon, a step onset at note 0, note 127,
 * sub-sample segments, overlapping repetitions whose Processing sum exceeds 1, and the longest icon the caps allow.
 */
class PinnedRenderHashesTest {
    private val icons = listOf(
        HapticIcon.STROKE,
        HapticIcon.HIT,
        HapticIcon.KNOCK,
        HapticIcon.HUG,
        HapticIcon("zero", 0.0, 0.0, 0.5, 0.0, 60.0),
        HapticIcon("step-note0", 0.0, 0.05, 0.8, 0.0, 0.0),
        HapticIcon("note127", 0.001, 0.02, 1.0, 0.004, 127.0, 0.03, 5),
        HapticIcon("subsample", 0.00003, 0.0001, 0.6, 0.00002, 69.0, 0.001, 7),
        HapticIcon("dense", 0.05, 0.02, 0.9, 0.08, 60.0, 0.03, 10),
        HapticIcon.LONGEST_ALLOWED,
    )

    private val rates = listOf(8_000, 44_100, 48_000)

    /** Each output of [icon] as one hash; an output that throws records the exception instead. */
    private fun hashes(icon: HapticIcon): Map<String, String> {
        val out = LinkedHashMap<String, String>()
        fun output(kind: String, block: Digest.() -> Unit) {
            out["${icon.name}/$kind"] = Digest().apply(block).hex()
        }
        output("stream-float") {
            forEachRender(icon) { renderer -> record { floats(renderer.stream(), 1000) } }
        }
        output("stream-double") {
            forEachRender(icon) { renderer -> record { doubles(renderer.stream(), 777) } }
        }
        output("sample-at") {
            for (model in EnvelopeModel.entries) record {
                val renderer = IconRenderer(icon, 8_000, model)
                for (i in 0 until renderer.sampleCount) double(renderer.sampleAt(i))
                for (i in 0 until renderer.sampleCount) double(renderer.envelopeAt(i))
            }
        }
        output("pcm") {
            for (rate in rates) for (model in EnvelopeModel.entries) for (mode in RenderMode.entries) record {
                val renderer = PcmRenderer(icon, rate, model, mode)
                shorts(renderer.toShortArray())
                pcm(renderer.stream(), 333)
                text(renderer.fidelity().toString())
            }
        }
        output("vibration-waveform") {
            for (model in EnvelopeModel.entries) {
                record { waveform(VibrationWaveform.amplitudeSteps(icon, model)) }
                record { waveform(VibrationWaveform.amplitudeSteps(icon, model, stepMillis = 3, maxEntries = 7)) }
                record { waveform(VibrationWaveform.onOff(icon, model)) }
                record { waveform(VibrationWaveform.onOff(icon, model, threshold = 0.2, stepMillis = 1)) }
            }
        }
        output("control-points") {
            for (model in EnvelopeModel.entries) {
                record { controlPoints(EnvelopeControlPoints.fit(icon, model)) }
                record { controlPoints(EnvelopeControlPoints.fit(icon, model, maxPoints = 4, minSegmentMillis = 5)) }
            }
        }
        output("envelope-signal") {
            for (rate in listOf(8_000, 44_100)) for (model in EnvelopeModel.entries) record {
                val envelope = icon.envelope(model, rate)
                double(envelope.length)
                val end = (icon.duration + 0.01) * 20_000
                var i = 0
                while (i <= end) {
                    double(envelope.sample(i / 20_000.0))
                    i++
                }
            }
        }
        output("pattern") {
            for (model in EnvelopeModel.entries) record {
                val pattern = icon.toPattern(model)
                text(pattern.name)
                for (key in pattern.amplitude) { double(key.time); double(key.amplitude) }
                for (key in pattern.frequency) { double(key.time); double(key.hertz) }
            }
        }
        output("pattern-outputs") {
            for (model in EnvelopeModel.entries) {
                val pattern = icon.toPattern(model)
                record { floats(pattern.signal().stream(8_000), 500) }
                record { waveform(pattern.vibrationWaveform()) }
                record { waveform(pattern.onOffWaveform()) }
                record { text(PatternEnvelope.of(pattern, EnvelopeEffectInfo.GUARANTEED, null).toString()) }
                record { text(PatternEnvelope.of(pattern, EnvelopeEffectInfo.GUARANTEED, 100.0..300.0).toString()) }
            }
        }
        return out
    }

    private fun Digest.forEachRender(icon: HapticIcon, block: Digest.(IconRenderer) -> Unit) {
        for (rate in rates) for (model in EnvelopeModel.entries) for (mode in RenderMode.entries) {
            record { block(IconRenderer(icon, rate, model, mode)) }
        }
    }

    @Test
    fun everyOutput_isBitForBitWhatItWas() {
        val actual = icons.fold(LinkedHashMap<String, String>()) { all, icon -> all.apply { putAll(hashes(icon)) } }
        // On a mismatch the whole table is printed, ready to paste once a change of output is deliberate.
        val table = actual.entries.joinToString("\n") { (key, hash) -> "        \"$key\" to \"$hash\"," }
        if (actual != EXPECTED) println(table)
        for ((key, hash) in actual) assertEquals(key, EXPECTED[key], hash)
        assertEquals(EXPECTED.keys, actual.keys)
    }

    /** SHA-256 over little-endian bytes; [record] logs an exception's class and message in place of the output. */
    private class Digest {
        private val sha = MessageDigest.getInstance("SHA-256")

        fun record(block: Digest.() -> Unit) {
            try {
                block()
            } catch (e: IllegalArgumentException) {
                text("threw ${e.javaClass.simpleName}: ${e.message}")
            }
        }

        fun double(value: Double) = sha.update(ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN).putDouble(value).array())

        fun long(value: Long) = sha.update(ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN).putLong(value).array())

        fun text(value: String) {
            val bytes = value.toByteArray(Charsets.UTF_8)
            long(bytes.size.toLong())
            sha.update(bytes)
        }

        fun shorts(values: ShortArray, count: Int = values.size) {
            val buffer = ByteBuffer.allocate(count * 2).order(ByteOrder.LITTLE_ENDIAN)
            for (i in 0 until count) buffer.putShort(values[i])
            sha.update(buffer.array())
        }

        fun floats(stream: SampleStream, block: Int) {
            val samples = FloatArray(block)
            drain(stream.totalSamples, 4, { stream.read(samples, 0, block) }) { buffer, i -> buffer.putFloat(samples[i]) }
        }

        fun doubles(stream: DoubleSampleStream, block: Int) {
            val samples = DoubleArray(block)
            drain(stream.totalSamples, 8, { stream.read(samples, 0, block) }) { buffer, i -> buffer.putDouble(samples[i]) }
        }

        fun pcm(stream: PcmStream, block: Int) {
            val samples = ShortArray(block)
            drain(stream.totalSamples, 2, { stream.read(samples, 0, block) }) { buffer, i -> buffer.putShort(samples[i]) }
        }

        /** The sample count, then every block [read] returns until -1, each sample [put] as [bytes] little-endian bytes. */
        private inline fun drain(total: Long, bytes: Int, read: () -> Int, put: (ByteBuffer, Int) -> Unit) {
            long(total)
            while (true) {
                val n = read()
                if (n < 0) break
                val buffer = ByteBuffer.allocate(n * bytes).order(ByteOrder.LITTLE_ENDIAN)
                for (i in 0 until n) put(buffer, i)
                sha.update(buffer.array())
            }
        }

        fun fidelity(fidelity: Fidelity) {
            double(fidelity.rmsError)
            double(fidelity.maxError)
            text(fidelity.description)
        }

        fun waveform(waveform: VibrationWaveform) {
            for (t in waveform.timings()) long(t)
            for (a in waveform.amplitudes()) long(a.toLong())
            long(waveform.stepMillis.toLong())
            fidelity(waveform.fidelity)
        }

        fun controlPoints(points: EnvelopeControlPoints) {
            for (point in points.points) {
                double(point.amplitude)
                double(point.frequencyHz)
                long(point.durationMillis)
            }
            fidelity(points.fidelity)
            double(points.relativeRmsError)
        }

        fun hex(): String = sha.digest().joinToString("") { "%02x".format(it) }
    }

    private companion object {
        val EXPECTED: Map<String, String> = mapOf(
        "stroke/stream-float" to "8aed1bc828ae51d18527acf7beb37a8f1cfac3df609109e416ba9ac7d438b6c0",
        "stroke/stream-double" to "739b89ebf180c26782b870dd7333a3227308acfc3bc80899649b559ac5c57028",
        "stroke/sample-at" to "85721e989c69819bd03ee10404cfc30c5d5a709192d564dc894abe55e8f43595",
        "stroke/pcm" to "eee5bd71b70746d12997fa5c3b2f06b30511656dc073859146cf5ab49ca323e3",
        "stroke/vibration-waveform" to "845ebd3b8de62a449e5a514d52f0ed19a90ae653e46340a5ba2097802ba292d9",
        "stroke/control-points" to "d92d18d8bf8ead9d8ee73c2ea0ae6021f117824b9cfa67dd006d4324c538e352",
        "stroke/envelope-signal" to "93857e803fa0e1ed069e730134a00d80061b8eeeb73f5e67e09f4300a2cf1fee",
        "stroke/pattern" to "d5bba29848ab5deca188216af026deb89a2de33bc22b686dd6101cb4a0a3d326",
        "stroke/pattern-outputs" to "8e4f9383a1c3225e3d8d222dde74241192194f2ea3858a152886bf7044869abf",
        "hit/stream-float" to "7b5a5575c83d4ec9892a29e8013a900c658a6bd6315faf3d973f1fbdca36f547",
        "hit/stream-double" to "ece552765ff103e628c761037627b73d64bd78680e7599687805c9184a2dad0b",
        "hit/sample-at" to "7b9265ee571c60df314c24067ddb196f74f8e098a33143bed949c9ecc13b2adc",
        "hit/pcm" to "86de0ebfcb871bb8edc5df89a80fb286daa3fdb32f54422a225ecd07a65db7f7",
        "hit/vibration-waveform" to "f4057ec3371ac295e493538c2919906c0cb2602bd64bcb84ccb09d18b9134384",
        "hit/control-points" to "3c8948001c8d9b0d851016e177a0cf8bb8976235dd081ef21054f178b690c431",
        "hit/envelope-signal" to "8bd50577bde6922db8ac417254ffe9392d74f3371e2b9a55315dba093a811575",
        "hit/pattern" to "fcbedc13207ee3d0b31dc7b35cefcd7e238c9d8263aaa35b2e14292b1a7f5936",
        "hit/pattern-outputs" to "a3bdbe8e23027f5f767bc8f68e9f830a892a1734fe1c7db3aabb11289269bc5c",
        "knock/stream-float" to "7efbccd6482b2dc0adf28f2efd79f27b5ab3b3cfd7b537b6f8220ca0fd74a7d8",
        "knock/stream-double" to "8bacd231b99e72377db9a4b4ab0f297db153428656f02e5e120f287138615c37",
        "knock/sample-at" to "df0ac4cb170cfd31468d654315e90d31dddb3536df482c5caaf5ec3984befc48",
        "knock/pcm" to "eda9768c5f91dd00ede68fc429d03138e06763b585bdaf2775e7e94545dacf5a",
        "knock/vibration-waveform" to "7cf284687a9aff27cd48f84a1b3c80984fecea7fda3a2b8a6e383d3ea4389268",
        "knock/control-points" to "9aec56a79b4c3ed52129710a7cb936acb71a957756fc09689938587484c11da9",
        "knock/envelope-signal" to "54f1fbfe39747343403422ba83f56babe42bfec18f367a04af8fb8ab3ce5a589",
        "knock/pattern" to "3dc475463c9789adefa6e65e115de7906bebf50c889e955827251e6282fba174",
        "knock/pattern-outputs" to "dbd2ea7e5c4eb9d836323f933a7b0d0affc692647500867a2357d04ea77c17ac",
        "hug/stream-float" to "09c67b7a8c7334a23b40c53c2673286d9e8742ba3565744cd3e255d830d49e12",
        "hug/stream-double" to "68177ae7b99e4382a875b46e86a5b423b9f55f1a32d847b4a1e2a790b7adb9db",
        "hug/sample-at" to "73ed74d32f647fe1751af8de951bccd419f22fb00b6453ef027582900a8060c3",
        "hug/pcm" to "a4333e06dc637473e61e510100d41815bd0d3046026c63dc7589372d4bedf4e8",
        "hug/vibration-waveform" to "ce3126037d63be9bf5165c4ab7749c9e0175571d7fb0e4ff85e60f014f11de8f",
        "hug/control-points" to "dbc7fb2a1dabc843505036c56667379421efe1c290443698e210c6fce7b592c8",
        "hug/envelope-signal" to "ea8b2a31fdfe71a4e9aa2fdde389315af808a6c606b3d99bd492f9517e529cf0",
        "hug/pattern" to "c659d2d8ff021e54080680d947dec849eb04b907ce6425d4a031ac83359126d6",
        "hug/pattern-outputs" to "7949122c1bf5c993fdea2637d8fce15cb04d7479e6b1ef0549000591f2d1663e",
        "zero/stream-float" to "2ea9ab9198d1638007400cd2c3bef1cc745b864b76011a0e1bc52180ac6452d4",
        "zero/stream-double" to "2ea9ab9198d1638007400cd2c3bef1cc745b864b76011a0e1bc52180ac6452d4",
        "zero/sample-at" to "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
        "zero/pcm" to "c01ae535daad9034e8a42e6bc911cf0aa90d22b2f4ae2acaf66ce646545e3b37",
        "zero/vibration-waveform" to "efc9c0465154a004aab5031c92bbd5ac9be10a8a924fd85d35e080f31915e3a8",
        "zero/control-points" to "7af610782077b1cb441dc3edf163da473ef6b3cd49614c26d40c1327ad0f0094",
        "zero/envelope-signal" to "3f2c7d671d4a2c210124550cf00f8e21727a0ae1a43e1758982a25725dde2b70",
        "zero/pattern" to "029a77fcc7e2279e651c724ae9fcdeb1456aadadf0d7559cfb5b48e227b4a470",
        "zero/pattern-outputs" to "eb0960ae25959842b34e1748987c54d17091de17fcef0e42fd1ab49945732e9b",
        "step-note0/stream-float" to "a26664129cdab5b2f5063b436e63e91c2708562f7ff11f0fef4ffafd09cbd27e",
        "step-note0/stream-double" to "3aa0824c14788cc0b9c73f9de66d3e2c24d4cb9d940e2b5e99175e5682b9cf63",
        "step-note0/sample-at" to "7af11adc9c74d34bd4ed429db17c5ddb0b845263e0c109a134fba523004be8e0",
        "step-note0/pcm" to "2b704beee606bf2db8049fa6050bdcaf0886be1c166880794969c291e08eac68",
        "step-note0/vibration-waveform" to "37d218fe8b4a9a16b8a5700ec63e0acbf3a47a1853020e7484a0491cbb08a799",
        "step-note0/control-points" to "b0fefdf1360cb74b3c84d0689f019f7117c6f22ed2f84ffc516d9242e82c1828",
        "step-note0/envelope-signal" to "39c182716b4760b70ef0070ddb0a05214b23b4d2d735ff9bd8e181acefb53dc8",
        "step-note0/pattern" to "ebb4b57959aa9ef8a25d4dbff763194cb1e00b27c656feafb048ef4904582c65",
        "step-note0/pattern-outputs" to "a62885e153b2c5f1375013c1033bf4c217308ec7b9c54b02073c17f63ced5d6d",
        "note127/stream-float" to "1a1f841d5d7f5414f3e98ef6cc2f00708a96a06998f2e280784df1777eb2daa0",
        "note127/stream-double" to "bcab3830e9e928b97cef8db5446e69cdeb381b9d9096268e46e8fc0d4762b776",
        "note127/sample-at" to "802ac1f20ecbdb81e109cefa7f4b75a60f1c9dd4248a2dcbff557af23004a283",
        "note127/pcm" to "730e691ee1d37e1caa4d678ff0a28a9cdcf0eb442ac8f1ca4299e4ff4c597689",
        "note127/vibration-waveform" to "ec92ac103557edef6d4e0500876094bb4e31b56506bf26f71a059dcd2d02de76",
        "note127/control-points" to "e79563ababbc4fc03b280b39f7366b04b94049c501651c78892c81ebea70e32e",
        "note127/envelope-signal" to "93bfed8eb32d045ea0049026a61feb56276458cb6aa05b6f500be692be59dce7",
        "note127/pattern" to "f8423f256505aa87d946c0fbdd2a4ebc7c65b6f039cbbdc16a38c7353cd2e69e",
        "note127/pattern-outputs" to "ad00fe5c4a82cd2786cf12e3bfa1a18a0844536a74b899a7467ba7c694eb5de7",
        "subsample/stream-float" to "584e10d0f1e7e407cb47e153e2bed1056e65313ca6139dcd4cab02018ff99d64",
        "subsample/stream-double" to "e485afe050e86b1cfce2168433d5b2b9dc0443e30352caca8cd8c8044a79084b",
        "subsample/sample-at" to "3a3913c6ff19db4904af34315cd49e4a4c609efc8b5b377c683359469f95e140",
        "subsample/pcm" to "a77d9659c7782d23706b55fb8d6e52b56fc223ed9f3017613b4fe106839433c6",
        "subsample/vibration-waveform" to "9cae402c0a857fb3b696d3354a97a1987dc3f6ea1cfd62b42366b8d3a66832e8",
        "subsample/control-points" to "80d55ccf5fc3da76842e891638af01a1ff0a21546ee543e75b12e3672c6d26b6",
        "subsample/envelope-signal" to "5f3fdd6969ec3eec90139fea58f9f0e882f3176d32f6001255d4ce3dd88a7439",
        "subsample/pattern" to "a532fad839f007e88f44d9eb94ca8d44d87b1fa7695828abf466a93e370fbfea",
        "subsample/pattern-outputs" to "af28568c1b367c6d8a6071577a88f87c504863a72290fc54ca5a28a3a881fc8f",
        "dense/stream-float" to "5fe3e308df29d1c3f1dc2c643475ec9ae6e0ee215f4f10161a2bf5292d23fef5",
        "dense/stream-double" to "a7c6fb5d894b7b8a67d1a3b51aa5140c1473090d31cf6bfa84bea12162ce490c",
        "dense/sample-at" to "e95870f2a6aef6087719de21c732f0aa9ad4bcf479112014de7a196ebe536842",
        "dense/pcm" to "3dc91520ea77a47ea03e572f2feeb25a68c487e5132e97b169950af9d7aaff5d",
        "dense/vibration-waveform" to "9a3b62ce408f3e406e2e5568c8f7371e725f9209d20e25bbe443eb246ff7701c",
        "dense/control-points" to "f826a977ebd8bc43f590fb8eed5082f87289fa87d598f3859f4c369f62735aca",
        "dense/envelope-signal" to "d242a67d03a44052a01b00e737c6fc620bec26cf5de67ba014eac16c20093f59",
        "dense/pattern" to "fce49c03802e66819ceec82c78a64eb280316bc0540c1d385a9a896d0600c1cc",
        "dense/pattern-outputs" to "ebd8e433a6d5e132c21595ccf2421421057ea577c5563a1184a3ff16b0a0a914",
        "longest/stream-float" to "f17ec238bdcb90bd1dc6a2114efa76d7f70d0f5d6ae0b2d65f1ddab448af1a11",
        "longest/stream-double" to "76c0f5b5c5224878bc37c87a917c57bfcc048d741014d4382fe7180e6215582c",
        "longest/sample-at" to "2f396268cee6c138b38a0583bcbce6d8d6b2cf001686ccb5b25e1de02d1259f4",
        "longest/pcm" to "a55c6329805eac8bc0056abb8055ab2ca931cad69582a9dddcc1edac06b082f9",
        "longest/vibration-waveform" to "5fbb46f53b0d2fe967f36670af368e3bd68102787646ad3097dbc671e1b1ccef",
        "longest/control-points" to "fec25dbca9b177c8aebe01f0fd79090f037d9b321ddf9c9a5edc8f302a6e678b",
        "longest/envelope-signal" to "4b4ea779806f0343c48710fc929dfbf613de1539c5541baa588f74891c2b7e78",
        "longest/pattern" to "f9d8d39da4494e573ea0ad1efde050edca6aac313262c60d00c67f6e9887b2d6",
        "longest/pattern-outputs" to "9c795a0968296721977e6db69b72275352b745249e2f07fddcc909793ff6e19e",
        )
    }
}
