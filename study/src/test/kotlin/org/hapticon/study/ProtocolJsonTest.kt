package org.hapticon.study

import org.hapticon.study.schema.ProtocolException
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.JsonException
import org.hapticon.study.design.OrderScheme
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.assertThrows
import org.junit.Test

class ProtocolJsonTest {
    @Test
    fun originatingStudy_roundTrips() {
        val text = ProtocolJson.encode(OriginatingStudy.PROTOCOL)
        assertEquals(OriginatingStudy.PROTOCOL, ProtocolJson.decode(text))
        assertEquals(OriginatingStudy.PROTOCOL, ProtocolJson.decode(ProtocolJson.encode(OriginatingStudy.PROTOCOL, indent = "")))
    }

    @Test
    fun originatingStudy_shape() {
        val p = OriginatingStudy.PROTOCOL
        assertEquals(listOf("icons", "text", "stickers"), p.tasks.map { it.id })
        assertEquals(listOf("icons"), p.fixedFirst)
        assertEquals(OrderScheme.PAPER, p.taskOrder)
        assertEquals(5, p.scale.points)
        assertEquals("strongly disagree", p.scale.labels.first())
        assertEquals("strongly agree", p.scale.labels.last())
        assertEquals(HapticIcon.PRESETS, p.tasks[0].stimuli.map { it.icon })
        assertEquals(listOf("stroking", "hitting", "knocking", "hugging"), p.tasks[0].stimuli.map { it.label })
        assertEquals("There, there. It'll be fine.", p.tasks[1].stimuli[0].text)
        assertEquals(listOf("sticker_stroke", "sticker_hit", "sticker_knock", "sticker_hug"), p.tasks[2].stimuli.map { it.sticker })
        assertEquals("This haptic icon enhances the effect of the text", p.tasks[1].question)
        assertEquals("This haptic icon enhances the touch effect of the sticker", p.tasks[2].question)
    }

    @Test
    fun minimalDocument_defaultsApply_unknownMembersIgnored() {
        val p = ProtocolJson.decode(
            """{"schema":"hapticon.study","version":1,"id":"s","title":"T","future":[1,2],"scale":{"points":2},
               "tasks":[{"id":"a","title":"A","question":"Q","stimuli":[{"id":"x","extra":true,"icon":${knock()}}]}]}""",
        )
        assertEquals(1, p.revision)
        assertEquals(org.hapticon.core.render.EnvelopeModel.PROCESSING, p.envelopeModel)
        assertEquals(OrderScheme.FIXED, p.taskOrder)
        assertEquals(OrderScheme.FIXED, p.tasks[0].stimulusOrder)
        assertEquals(emptyList<String>(), p.fixedFirst)
        assertEquals(emptyList<String>(), p.scale.labels)
        assertEquals("", p.tasks[0].instructions)
        assertEquals(Stimulus("x", HapticIcon.KNOCK), p.tasks[0].stimuli[0])
    }

    @Test
    fun errors_nameTheFieldPath() {
        expect("schema: expected \"hapticon.study\", got \"hapticon.icon\"") { it.replace("\"hapticon.study\"", "\"hapticon.icon\"") }
        expect("version: unsupported hapticon.study version 2 (this build reads version 1)") { it.replace("\"version\":1,\"id\"", "\"version\":2,\"id\"") }
        expect("title: missing") { it.replace("\"title\":\"T\",", "") }
        expect("scale.points: expected an integer, got 4.5") { it.replace("\"points\":5", "\"points\":4.5") }
        expect("scale.points: must be in 2..11, was 1") { it.replace("\"points\":5", "\"points\":1") }
        expect("tasks[0].stimuli[1].icon.attack: must be a finite number of seconds >= 0, was -1.0") {
            it.replace("\"id\":\"y\",\"icon\":{\"schema\":\"hapticon.icon\",\"version\":1,\"name\":\"knock\",\"attack\":0.005", "\"id\":\"y\",\"icon\":{\"schema\":\"hapticon.icon\",\"version\":1,\"name\":\"knock\",\"attack\":-1")
        }
        expect("tasks[0].stimuli[1].icon: expected an object, got \"knock\"") { it.replace(Regex("(\"id\":\"y\",\"icon\":)\\{[^}]*}"), "$1\"knock\"") }
        expect("tasks[0].stimuli[1].id: duplicate stimulus id \"x\" in task \"a\"") { it.replace("\"id\":\"y\"", "\"id\":\"x\"") }
        expect("tasks[1].id: duplicate task id \"a\"") { it.replace("\"id\":\"b\"", "\"id\":\"a\"") }
        expect("tasks[1].stimuli: task \"b\" has no stimuli") { it.replace(Regex("(\"id\":\"b\".*\"stimuli\":)\\[.*]}]}$"), "$1[]}]}") }
        expect("tasks[0].stimulusOrder: expected \"fixed\", \"paper\", \"full\", \"williams\", \"random\", got \"latin\"") { it.replace("\"stimulusOrder\":\"williams\"", "\"stimulusOrder\":\"latin\"") }
        expect("tasks[0].question: unknown placeholder {nn}; use {n}, {label}, {icon}, {text}, {sticker}") { it.replace("icon {n}", "icon {nn}") }
        expect("fixedFirst[0]: no task has id \"zz\"") { it.replace("\"fixedFirst\":[\"a\"]", "\"fixedFirst\":[\"zz\"]") }
        expect("fixedFirst[1]: task \"a\" is listed twice") { it.replace("\"fixedFirst\":[\"a\"]", "\"fixedFirst\":[\"a\",\"a\"]") }
        expect("tasks: a study needs at least one task") { it.replace(Regex("\"tasks\":\\[.*]}$"), "\"tasks\":[]}") }
        expect("tasks[0].stimuli[0].sticker: expected 1..64 of A-Z a-z 0-9 _ . -, got \"a b\"") { it.replace("\"id\":\"x\",", "\"id\":\"x\",\"sticker\":\"a b\",") }
        expect("scale.labels: expected none, 2 anchors or 5 labels, got 3") { it.replace("\"labels\":[]", "\"labels\":[\"a\",\"b\",\"c\"]") }
        expect("envelopeModel: expected \"paper\", \"processing\", got \"jsyn\"") { it.replace("\"title\":\"T\",", "\"title\":\"T\",\"envelopeModel\":\"jsyn\",") }
        expect("tasks[1]: expected an object, got 3") { it.replace(Regex("(\"tasks\":\\[\\{.*?}]}),\\{.*]}$"), "$1,3]}") }
    }

    @Test
    fun envelopeModel_paperRoundTripsAndIsWrittenByName() {
        val paper = OriginatingStudy.PROTOCOL.copy(envelopeModel = org.hapticon.core.render.EnvelopeModel.PAPER)
        val text = ProtocolJson.encode(paper, "")
        assertTrue(text, text.contains("\"envelopeModel\":\"paper\""))
        assertEquals(paper, ProtocolJson.decode(text))
        assertTrue(ProtocolJson.encode(OriginatingStudy.PROTOCOL, "").contains("\"envelopeModel\":\"processing\""))
    }

    @Test
    fun notAnObject_andNotJson() {
        assertEquals("protocol: expected an object, got an array", assertThrows(ProtocolException::class.java) { ProtocolJson.decode("[]") }.message)
        assertEquals(1, assertThrows(JsonException::class.java) { ProtocolJson.decode("{") }.offset)
    }

    @Test
    fun largeProtocol_roundTrips_overTheLimitIsAJsonError() {
        val stimuli = (0 until 100).map { Stimulus("s$it", HapticIcon.HIT, text = "t\"ext,\n$it") }
        val p = StudyProtocol("big", "Big", LikertScale(7), (0 until 20).map { StudyTask("t$it", "T", "", stimuli, "Q {n}", OrderScheme.RANDOM) }, OrderScheme.FULL)
        assertEquals(p, ProtocolJson.decode(ProtocolJson.encode(p, "")))
        val tooBig = p.copy(tasks = p.tasks + (20 until 40).map { p.tasks[0].copy(id = "t$it") })
        val e = assertThrows(JsonException::class.java) { ProtocolJson.decode(ProtocolJson.encode(tooBig)) }
        assertTrue(e.message, e.message!!.endsWith("exceeds the limit of 1048576 at offset 1048576"))
    }

    private fun knock() = org.hapticon.core.io.IconJson.encode(HapticIcon.KNOCK)

    private fun expect(message: String, edit: (String) -> String) {
        val text = edit(VALID)
        assertEquals(text, message, assertThrows(text, ProtocolException::class.java) { ProtocolJson.decode(text) }.message)
    }

    private companion object {
        private val KNOCK = org.hapticon.core.io.IconJson.encode(HapticIcon.KNOCK)
        val VALID = """{"schema":"hapticon.study","version":1,"id":"s","title":"T","scale":{"points":5,"labels":[]},""" +
            """"taskOrder":"paper","fixedFirst":["a"],"tasks":[{"id":"a","title":"A","question":"Haptic icon {n}","stimulusOrder":"williams",""" +
            """"stimuli":[{"id":"x","icon":$KNOCK},{"id":"y","icon":$KNOCK}]},{"id":"b","title":"B","question":"Q","stimuli":[{"id":"z","icon":$KNOCK}]}]}"""
    }
}
