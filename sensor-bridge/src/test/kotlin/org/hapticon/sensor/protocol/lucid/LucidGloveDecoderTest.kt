package org.hapticon.sensor.protocol.lucid

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.Recorder
import org.hapticon.sensor.protocol.ascii
import org.hapticon.sensor.protocol.feedInChunks
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame.Companion.ABSENT
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class LucidGloveDecoderTest {
    private val recorder = Recorder()

    /** Decodes [line] and returns a copy of what the listener saw, or fails if nothing was delivered. */
    private class Snapshot(frame: LucidGloveFrame) {
        val curl = frame.curl.copyOf()
        val splay = frame.splay.copyOf()
        val joints = frame.jointCurl.copyOf()
        val joystickX = frame.joystickX
        val joystickY = frame.joystickY
        val trigger = frame.trigger
        val pressed = LucidButton.entries.filter { frame.isPressed(it) }.toSet()
    }

    private fun decodeOne(line: String): Snapshot {
        val snapshots = ArrayList<Snapshot>()
        val decoder = LucidGloveDecoder({ snapshots += Snapshot(it) })
        decoder.feed(ascii(line))
        assertEquals(decoder.stats.toString(), 1, snapshots.size)
        return snapshots.single()
    }

    @Test
    fun feed_firmwareLineWithSplay_decodesEveryField() {
        // The firmware's sprintf order with USING_SPLAY: curls, joystick, trigger, flags, splay.
        val f = decodeOne("A0B577C1154D1731E2308F2048G2047P288HJL(AB)2048(BB)2058(CB)2068(DB)2078(EB)2088\n")
        assertArrayEquals(intArrayOf(0, 577, 1154, 1731, 2308), f.curl)
        assertArrayEquals(intArrayOf(2048, 2058, 2068, 2078, 2088), f.splay)
        assertEquals(2048, f.joystickX)
        assertEquals(2047, f.joystickY)
        assertEquals(288, f.trigger)
        assertEquals(setOf(LucidButton.JOYSTICK_CLICK, LucidButton.A, LucidButton.GRAB), f.pressed)
        assertArrayEquals(IntArray(20) { ABSENT }, f.joints)
    }

    @Test
    fun feed_eachFlagLetter_setsItsButtonOnly() {
        val expected = mapOf('H' to LucidButton.JOYSTICK_CLICK, 'I' to LucidButton.TRIGGER, 'J' to LucidButton.A, 'K' to LucidButton.B,
            'L' to LucidButton.GRAB, 'M' to LucidButton.PINCH, 'N' to LucidButton.MENU, 'O' to LucidButton.CALIBRATE)
        for ((letter, button) in expected) {
            assertEquals(letter, button.key)
            assertEquals("$letter", setOf(button), decodeOne("A1B2C3D4E5$letter\n").pressed)
        }
        assertEquals(LucidButton.entries.toSet(), expected.values.toSet())
    }

    @Test
    fun feed_onlyCurls_optionalValuesAbsent() {
        val f = decodeOne("A1B2C3D4E5\n")
        assertArrayEquals(intArrayOf(1, 2, 3, 4, 5), f.curl)
        assertEquals(ABSENT, f.joystickX)
        assertEquals(ABSENT, f.joystickY)
        assertEquals(ABSENT, f.trigger)
        assertArrayEquals(IntArray(5) { ABSENT }, f.splay)
        assertEquals(emptySet<LucidButton>(), f.pressed)
    }

    @Test
    fun feed_jointKeys_decodeByFingerAndJoint() {
        val f = decodeOne("(AAA)1(AAD)2(EAA)3(EAD)4(CAB)5A0B0C0D0E0\n")
        val joints = IntArray(20) { ABSENT }
        joints[0] = 1
        joints[3] = 2
        joints[16] = 3
        joints[19] = 4
        joints[2 * 4 + 1] = 5
        assertArrayEquals(joints, f.joints)
    }

    @Test
    fun feed_keysInAnyOrderAndRepeated_lastValueWins() {
        val f = decodeOne("E5D4IC3B2A1A9\n")
        assertArrayEquals(intArrayOf(9, 2, 3, 4, 5), f.curl)
        assertEquals(setOf(LucidButton.TRIGGER), f.pressed)
    }

    @Test
    fun feed_keysTheEncodingDoesNotDefine_areSkippedWithTheirDigits() {
        val f = decodeOne("A1B2C3D4E5Q77Z(ZB)9(AX)8(AAE)7(ABCD)6\n")
        assertArrayEquals(intArrayOf(1, 2, 3, 4, 5), f.curl)
        assertArrayEquals(IntArray(5) { ABSENT }, f.splay)
        assertArrayEquals(IntArray(20) { ABSENT }, f.joints)
    }

    @Test
    fun feed_badLinesAfterFirstFrame_countedByKind() {
        val decoder = LucidGloveDecoder(recorder)
        decoder.feed(ascii("A1B2C3D4E5\n" + "A1B2C3D4\n" + "A1B2C3D4E5F\n" + "A1B2C3D4E5 \n" + "a1B2C3D4E5\n" +
            "A1B2C3D4E5(AB\n" + "A1B2C3D4E5(AB)\n" + "A1234567890B2C3D4E5\n" + "A-1B2C3D4E5\n" + "A1B2C3D4E5\n"))
        assertEquals(2L, decoder.stats.frames)
        assertEquals(1L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
        assertEquals(7L, decoder.stats.badFrames(FrameError.SYNTAX))
        assertEquals(8L, decoder.stats.badFrames)
        assertEquals(9L + 12 + 12 + 11 + 14 + 15 + 20 + 12, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_bannerBeforeFirstFrame_isIgnored() {
        val decoder = LucidGloveDecoder(recorder)
        decoder.feed(ascii("LucidGloves ready\n\nA1B2C3D4E5\n\n"))
        assertEquals(listOf("A1B2C3D4E5"), recorder.events)
        assertEquals(3L, decoder.stats.ignoredLines)
        assertEquals(0L, decoder.stats.badFrames)
        assertEquals(18L + 1 + 1, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_crlf_decodes() {
        decodeOne("A1B2C3D4E5J\r\n")
    }

    @Test
    fun feed_oneByteAtATime_sameFramesAndStats() {
        val text = ascii("banner\nA1B2C3D4E5F6G7P8HI(AB)9\r\nA1B2\nA10B20C30D40E50LMNO\n" + "A".repeat(300) + "\nA0B0C0D0E0\nA1B")
        val whole = Recorder()
        val wholeDecoder = LucidGloveDecoder(whole)
        wholeDecoder.feed(text)
        wholeDecoder.finish()
        assertEquals(listOf("A1B2C3D4E5F6G7P8HI(AB)9", "A10B20C30D40E50LMNO", "A0B0C0D0E0"), whole.events)
        for (chunk in listOf(1, 2, 5, 64)) {
            val split = Recorder()
            val splitDecoder = LucidGloveDecoder(split)
            splitDecoder.feedInChunks(text, chunk)
            splitDecoder.finish()
            assertEquals(whole.events, split.events)
            assertEquals(wholeDecoder.stats.toString(), splitDecoder.stats.toString())
        }
        assertEquals(1L, wholeDecoder.stats.badFrames(FrameError.OVERLONG))
        assertEquals(1L, wholeDecoder.stats.badFrames(FrameError.TRUNCATED))
    }

    @Test
    fun frame_toString_rebuildsTheLine() {
        val line = "A10B20C30D40E50F1G2P3HIJKLMNO(AB)1(BB)2(CB)3(DB)4(EB)5(AAA)6(EAD)7"
        val decoder = LucidGloveDecoder(recorder)
        decoder.feed(ascii("$line\n"))
        assertEquals(listOf(line), recorder.events)
    }

    @Test
    fun isPressed_afterALineWithoutFlags_isFalse() {
        val decoder = LucidGloveDecoder({ frame -> recorder.events += LucidButton.entries.filter(frame::isPressed).joinToString() })
        decoder.feed(ascii("A1B2C3D4E5HIJKLMNO\nA1B2C3D4E5\n"))
        assertEquals(listOf(LucidButton.entries.joinToString(), ""), recorder.events)
    }
}
