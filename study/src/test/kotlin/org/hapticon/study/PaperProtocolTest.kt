package org.hapticon.study

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.study.log.StudyEvent
import org.junit.Assert.assertEquals
import org.junit.Test

class PaperProtocolTest {
    private val paper = OriginatingStudy.PAPER_PROTOCOL

    @Test
    fun paperProtocol_states_sixteenParticipantsWhiteNoiseProcessingTogether() {
        assertEquals(16, paper.participants)
        assertEquals(Masking.WHITE, paper.masking)
        assertEquals(EnvelopeModel.PROCESSING, paper.envelopeModel)
        assertEquals(listOf(TaskPresentation.TOGETHER, TaskPresentation.TOGETHER, TaskPresentation.TOGETHER), paper.tasks.map { it.presentation })
        assertEquals(listOf(1, 2, 3, 4), paper.task("icons")!!.stimuli.map { it.number })
        assertEquals(HapticIcon.PRESETS, paper.task("icons")!!.stimuli.map { it.icon })
        assertEquals(paper, ProtocolJson.decode(ProtocolJson.encode(paper)))
    }

    @Test
    fun plan_paperProtocol_iconsFirstThenTextAndStickersAlternateAcrossParticipants() {
        val orders = (0 until 16).map { p -> StudyPlan.of(paper, p).schedule.tasks.map { it.id } }
        for ((p, order) in orders.withIndex()) {
            val expected = if (p % 2 == 0) listOf("icons", "text", "stickers") else listOf("icons", "stickers", "text")
            assertEquals("participant $p", expected, order)
        }
        // Balanced over the 16: eight of each order.
        assertEquals(8, orders.count { it[1] == "text" })
    }

    @Test
    fun plan_paperProtocol_showsTheFourIconsTogetherThenAsksTheItemsByIconNumber() {
        val steps = StudyPlan.of(paper, 1).steps
        assertEquals(StudyStep.TaskIntro(paper.task("icons")!!, 1), steps[0])
        val explore = steps[1] as StudyStep.Explore
        assertEquals(listOf("stroke", "hit", "knock", "hug"), explore.stimuli.map { it.icon.name })
        val items = steps.drop(2).take(4).map { (it as StudyStep.Trial).question }
        assertEquals(
            listOf("Haptic icon 1 feels like stroking", "Haptic icon 2 feels like hitting", "Haptic icon 3 feels like knocking", "Haptic icon 4 feels like hugging"),
            items,
        )
        assertEquals(StudyStep.TaskEnd(paper.task("icons")!!, 1), steps[6])
        // Participant 1's second task is stickers: its items name the icons by number too.
        assertEquals("Haptic icon 2 enhances the touch effect of its sticker", (steps[10] as StudyStep.Trial).question)
    }

    @Test
    fun session_exploreStep_isLeftByExplorationEndedAndResumesThere() {
        val plan = StudyPlan.of(paper, 0)
        val session = StudySession(plan)
        val started = listOf(StudyEvent.SessionStarted(paper.id, paper.revision, 0, 0L), StudyEvent.TaskStarted("icons"))
        assertEquals(StudyStep.Explore::class, session.nextStep(started)::class)
        // Pressing icons does not leave the screen; ExplorationEnded does.
        val pressed = started + StudyEvent.IconPressed("icons", "stroke") + StudyEvent.IconPressed("icons", "hug")
        assertEquals(StudyStep.Explore::class, session.nextStep(pressed)::class)
        val next = session.nextStep(pressed + StudyEvent.ExplorationEnded("icons")) as StudyStep.Trial
        assertEquals("stroke", next.stimulus.id)
        assertEquals(StudyEvent.ExplorationEnded("icons"), StudyEvent.of(StudyEvent.EXPLORATION_ENDED, StudyEvent.payload(StudyEvent.ExplorationEnded("icons"))))
    }
}
