#pragma once
// Where Debian's packages install the data the studio and the CLI read, in this one place
// (tests/layout keeps it so). Each can be replaced: by an option, or by one of util/Environment's
// variables.
namespace lipsync::systempaths {

// pocketsphinx-en-us: CMU Sphinx's US-English acoustic model folder, and the CMU pronouncing
// dictionary beside it.
inline constexpr const char *kSphinxModelDir = "/usr/share/pocketsphinx/model/en-us/en-us";
inline constexpr const char *kCmuDictionary = "/usr/share/pocketsphinx/model/en-us/cmudict-en-us.dict";
// libopencv-dev: the Haar cascade of frontal faces (the face detector's last resort).
inline constexpr const char *kHaarCascade = "/usr/share/opencv4/haarcascades/haarcascade_frontalface_alt2.xml";
// libdlib-data: dlib's 68-point face shape predictor.
inline constexpr const char *kDlibPredictor = "/usr/share/dlib/shape_predictor_68_face_landmarks.dat";

} // namespace lipsync::systempaths
