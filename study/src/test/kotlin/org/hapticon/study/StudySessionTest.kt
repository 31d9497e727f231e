package org.hapticon.study

import org.hapticon.core.HapticIcon
import org.hapticon.study.design.OrderScheme
import org.hapticon.study.ParticipantSchedule
import org.hapticon.study.log.EventLog
import org.hapticon.study.log.StudyEvent
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class StudySessionTest {
    private val protocol = OriginatingStudy.PROTOCOL

    @Test
    fun schedule_originatingStudy_iconsFirstThenAlternates() {
        assertEquals(listOf("icons", "text", "stickers"), ParticipantSchedule.of(protocol, 0).tasks.map { it.id })
        assertEquals(listOf("icons", "stickers", "text"), ParticipantSchedule.of(protocol, 1).tasks.map { it.id })
        assertEquals(listOf("icons", "text", "stickers"), ParticipantSchedule.of(protocol, 2).tasks.map { it.id })
        assertEquals(listOf("stroke", "hit", "hug", "knock"), ParticipantSchedule.of(protocol, 0).stimuli.getValue("icons").map { it.id })
        assertEquals(listOf("hit", "knock", "stroke", "hug"), ParticipantSchedule.of(protocol, 1).stimuli.getValue("icons").map { it.id })
    }

    @Test
    fun schedule_isAPureFunction_randomDependsOnSeedOnly() {
        val random = protocol.copy(taskOrder = OrderScheme.RANDOM, fixedFirst = emptyList(), tasks = protocol.tasks.map { it.copy(stimulusOrder = OrderScheme.RANDOM) })
        val a = ParticipantSchedule.of(random, 5, seed = 99)
        val b = ParticipantSchedule.of(random, 5, seed = 99)
        assertEquals(a.tasks, b.tasks)
        assertEquals(a.stimuli, b.stimuli)
        val seeds = (0L until 20L).map { ParticipantSchedule.of(random, 5, it).let { s -> s.tasks.map { t -> t.id } to s.stimuli.values.toList() } }
        assertTrue(seeds.toSet().size > 10)
    }

    @Test
    fun plan_participant0_stepsAndQuestions() {
        val plan = StudyPlan.of(protocol, 0)
        assertEquals("P000-A", plan.participantId)
        assertEquals(1 + 3 * 6, plan.steps.size)
        assertEquals(StudyStep.TaskIntro(protocol.tasks[0], 1), plan.steps[0])
        assertEquals(
            listOf("Haptic icon 1 feels like stroking", "Haptic icon 2 feels like hitting", "Haptic icon 3 feels like hugging", "Haptic icon 4 feels like knocking"),
            plan.trials.take(4).map { it.question },
        )
        assertEquals(StudyStep.TaskEnd(protocol.tasks[0], 1), plan.steps[5])
        assertEquals(StudyStep.TaskIntro(protocol.tasks[1], 2), plan.steps[6])
        assertEquals("This haptic icon enhances the effect of the text", plan.trials[4].question)
        assertEquals(StudyStep.Done, plan.steps.last())
        assertEquals(12, plan.trials.size)
    }

    @Test
    fun nextStep_walksThePlan_andResumesFromTheLogAlone() {
        val plan = StudyPlan.of(protocol, 3)
        val session = StudySession(plan)
        val log = EventLog.start(plan.participantId)
        log.append(StudyEvent.SessionStarted(protocol.id, 1, 3, 0L), 1_000)
        var now = 1_000L
        val visited = ArrayList<StudyStep>()
        while (true) {
            // Every turn starts from the log alone, as after the app was killed and restarted.
            val resumed = EventLog.resume(plan.participantId, log.entries).events
            val step = StudySession(StudyPlan.ofSession(protocol, resumed)).nextStep(resumed)
            visited += step
            now += 10
            when (step) {
                is StudyStep.TaskIntro -> log.append(StudyEvent.TaskStarted(step.task.id), now)
                is StudyStep.Explore -> log.append(StudyEvent.ExplorationEnded(step.task.id), now)
                is StudyStep.Trial -> {
                    log.append(StudyEvent.StimulusShown(step.task.id, step.stimulus.id), now)
                    log.append(StudyEvent.IconPressed(step.task.id, step.stimulus.id), now + 1)
                    assertEquals(step, session.nextStep(log.events))
                    log.append(StudyEvent.Answer(step.task.id, step.stimulus.id, 3), now + 2)
                }
                is StudyStep.TaskEnd -> log.append(StudyEvent.TaskEnded(step.task.id), now)
                StudyStep.Done -> break
            }
        }
        assertEquals(plan.steps, visited)
        assertFalse(session.isFinished(log.events))
        log.append(StudyEvent.SessionEnded, now)
        assertTrue(session.isFinished(log.events))
        assertEquals(12, session.answeredTrials(log.events))
    }

    @Test
    fun nextStep_midTask_isTheFirstUnansweredTrial() {
        val plan = StudyPlan.of(protocol, 0)
        val trials = plan.trials
        val events = listOf(
            StudyEvent.SessionStarted(protocol.id, 1, 0, 0L),
            StudyEvent.TaskStarted("icons"),
            StudyEvent.StimulusShown("icons", trials[0].stimulus.id),
            StudyEvent.Answer("icons", trials[0].stimulus.id, 5),
            StudyEvent.StimulusShown("icons", trials[1].stimulus.id),
            StudyEvent.PlaybackStarted("icons", trials[1].stimulus.id),
        )
        assertEquals(trials[1], StudySession(plan).nextStep(events))
        assertEquals(1, StudySession(plan).answeredTrials(events))
        assertEquals(plan.steps[0], StudySession(plan).nextStep(emptyList()))
    }

    @Test
    fun ofSession_needsAMatchingSessionStarted() {
        assertEquals(StudyPlan.of(protocol, 9, 4).steps, StudyPlan.ofSession(protocol, listOf(StudyEvent.SessionStarted(protocol.id, 1, 9, 4))).steps)
        for ((events, message) in listOf(
            emptyList<StudyEvent>() to "the log has no session_started event",
            listOf(StudyEvent.SessionStarted(protocol.id, 2, 0, 0)) to "the session ran protocol hapticon-icons revision 2, not hapticon-icons revision 1",
        )) {
            assertEquals(message, assertThrows(IllegalArgumentException::class.java) { StudyPlan.ofSession(protocol, events) }.message)
        }
    }

    @Test
    fun oneTaskOneStimulus_smallestPlan() {
        val tiny = StudyProtocol("t", "T", LikertScale(2), listOf(StudyTask("a", "A", "", listOf(Stimulus("x", HapticIcon.HUG)), "Is it {icon}?")))
        val plan = StudyPlan.of(tiny, 0)
        assertEquals(4, plan.steps.size)
        assertEquals("Is it hug?", plan.trials.single().question)
        assertNotEquals(StudyStep.Done, StudySession(plan).nextStep(emptyList()))
    }
}
