package org.hapticon.companion.replicate

import org.hapticon.gesture.synthetic.NaoSyntheticPeople

/** Every replication `hapticon replicate` knows, in id order: the papers' seed-file numbers. */
val allReplications: List<Replication> = listOf(
    HapticIconsReplication,
    SocialTouchReplication(),
    HandshakeCalibrationReplication,
    ComplianceGrainsReplication,
    NaoGesturesReplication { NaoSyntheticPeople.sessions(count = NaoGesturesReplication.SIMULATED_PEOPLE) },
)
