package org.hapticon.companion.sensors

import org.hapticon.companion.cli
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File

class HandshakeCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun file(name: String, text: String): File = temp.newFile(name).also { it.writeText(text) }

    private val header = "time_s,active," +
        "thumb_v,thumb_deg,thumb_servo,thumb_amp,index_v,index_deg,index_servo,index_amp,middle_v,middle_deg,middle_servo,middle_amp," +
        "ring_v,ring_deg,ring_servo,ring_amp,pinky_v,pinky_deg,pinky_servo,pinky_amp,palm_v,palm_deg,palm_amp"

    @Test
    fun handshake_workedExample_printsRestThenTheRegionCommands() {
        val self = file("self.csv", "time_s,thumb_deg,middle_deg\n0,0,0\n0.01,50,105\n")
        // The partner's row at 0.005 s is held for the self row at 0.01 s.
        val partner = file("partner.csv", "time_s,thumb_deg,middle_deg\n# partner grips\n0.005,0,67.95\n")
        val result = cli("handshake", "--self", self.path, "--partner", partner.path)
        assertEquals(result.toString(), 0, result.exitCode)
        // docs/sensor-models.md's worked example: the thumb gets 0.635·1.64 + 0.93 = 1.9714 V, the palm 2.19145 V.
        // Thumb: angle 0.635·190° = 120.65°, servo round(1000·0.635) = 635, amplitude round(40 + 215·0.635) = 177.
        val lines = listOf(
            header,
            "0.000000,0,0.0000,0.00,0,0,0.0000,0.00,0,0,0.0000,0.00,0,0,0.0000,0.00,0,0,0.0000,0.00,0,0,0.0000,0.00,0",
            "0.010000,1,1.9714,120.65,635,177,0.9220,114.00,600,169,1.7288,125.40,660,182,0.8088,113.05,595,168," +
                "1.1081,111.15,585,166,2.1915,103.85,112",
        )
        assertEquals(lines.joinToString("\n", postfix = "\n"), result.stdout)
        assertEquals(listOf("handshake: 2 steps, active in 1"), result.stderrLines)
    }

    @Test
    fun handshake_badPartnerLine_exitsTwoNamingThePartnerFile() {
        val self = file("self.csv", "time_s,thumb_deg,middle_deg\n0,0,0\n")
        val partner = file("partner.csv", "time_s,thumb_deg,middle_deg\n0,0,0\n0.01,0,x\n")
        val result = cli("handshake", "--self", self.path, "--partner", partner.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: $partner:3: middle_deg is not a number: \"x\""), result.stderrLines)
        assertEquals("", result.stdout)
    }

    @Test
    fun handshake_selfTimeGoingBack_exitsTwoNamingTheSelfFile() {
        val self = file("self.csv", "time_s,thumb_deg,middle_deg\n0.5,0,0\n0.5,0,0\n")
        val partner = file("partner.csv", "time_s,thumb_deg,middle_deg\n0,0,0\n")
        val result = cli("handshake", "--self", self.path, "--partner", partner.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: $self:3: time must increase, 0.5 s after 0.5 s"), result.stderrLines)
    }

    @Test
    fun handshake_missingOptionOrFile_exitsTwo() {
        val self = file("self.csv", "time_s,thumb_deg,middle_deg\n0,0,0\n")
        val noPartner = cli("handshake", "--self", self.path)
        assertEquals(2, noPartner.exitCode)
        assertEquals(listOf("hapticon: handshake needs --partner"), noPartner.stderrLines)
        val missing = File(temp.root, "none.csv")
        val missingFile = cli("handshake", "--self", self.path, "--partner", missing.path)
        assertEquals(2, missingFile.exitCode)
        assertEquals(listOf("hapticon: --partner: no such file: $missing"), missingFile.stderrLines)
    }
}
