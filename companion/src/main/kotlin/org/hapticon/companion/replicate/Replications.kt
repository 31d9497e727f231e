package org.hapticon.companion.replicate

import org.hapticon.gesture.synthetic.NaoSyntheticPeople

/** Every replication `hapticon replicate` knows, in id order. */
val allReplications: List<Replication> = listOf(
    HapticIconsReplication,
    ComplianceGrainsReplication,
    NaoGesturesReplication { NaoSyntheticPeople.sessions(count = 8, takesPerClass = 3) },
    SocialTouchReplication(),
    HandshakeCalibrationReplication,
)
