#include "project/Sequence.h"

namespace lipsync {

bool Sequence::operator==(const Sequence &other) const
{
    // Eigen's == on matrices of different sizes asserts, so compare the shapes first.
    const bool sameFeatures = features.rows() == other.features.rows()
                              && features.cols() == other.features.cols()
                              && (features.size() == 0 || features == other.features);
    return sameFeatures && id == other.id && mediaFile == other.mediaFile
           && frameRate == other.frameRate && frameCount == other.frameCount
           && transcript == other.transcript
           && transcriptProposed == other.transcriptProposed && landmarks == other.landmarks
           && words == other.words && phones == other.phones && fitErrors == other.fitErrors;
}

} // namespace lipsync
