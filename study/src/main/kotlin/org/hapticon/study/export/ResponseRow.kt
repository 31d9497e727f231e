package org.hapticon.study.export

/**
 * One response in long format: one row per answered trial, as in the CSV [ResponseCsv] reads and writes.
 *
 * @property studyId the protocol id (`study_id`).
 * @property protocolVersion the protocol's revision (`protocol_version`).
 * @property envelopeModel the envelope model the participant felt (`envelope_model`: `processing` or `paper`).
 * @property participant the pseudonymous participant id.
 * @property participantIndex the 0-based participant index.
 * @property task the task id.
 * @property taskPosition the task's 1-based position in this participant's order.
 * @property trial the stimulus's 1-based position within the task for this participant.
 * @property stimulus the stimulus id.
 * @property icon the icon's name.
 * @property text the message text shown with the icon, or null.
 * @property sticker the sticker id shown with the icon, or null.
 * @property question the statement as the participant read it.
 * @property response the rating, 1..scale points.
 * @property responseTimeMillis answer time minus the last StimulusShown of the trial, or null when it was not shown.
 * @property iconPresses how many times the participant pressed the icon during the trial.
 * @property answeredAtMillis when the answer was recorded, epoch milliseconds.
 */
public data class ResponseRow(
    val studyId: String,
    val protocolVersion: Int,
    val envelopeModel: String,
    val participant: String,
    val participantIndex: Int,
    val task: String,
    val taskPosition: Int,
    val trial: Int,
    val stimulus: String,
    val icon: String,
    val text: String?,
    val sticker: String?,
    val question: String,
    val response: Int,
    val responseTimeMillis: Long?,
    val iconPresses: Int,
    val answeredAtMillis: Long,
)
