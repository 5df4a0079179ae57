#include "aam/AutoLandmarks.h"

#include "aam/AamFitter.h"
#include "aam/LandmarkScheme.h"
#include "util/Error.h"

namespace lipsync {

bool parseAutoLandmarkMethod(const std::string &name, AutoLandmarkMethod &method)
{
    if (name == "auto")
        method = AutoLandmarkMethod::Auto;
    else if (name == "dlib")
        method = AutoLandmarkMethod::Dlib;
    else if (name == "aam")
        method = AutoLandmarkMethod::Aam;
    else if (name == "template")
        method = AutoLandmarkMethod::Template;
    else
        return false;
    return true;
}

AutoLandmarks detectAutoLandmarks(const cv::Mat &bgr, const FaceDetection &face, FaceDetector &detector,
                                  AutoLandmarkMethod method, const AamFitter *fitter)
{
    AutoLandmarks out;
    const bool dlibAllowed = method == AutoLandmarkMethod::Auto || method == AutoLandmarkMethod::Dlib;
    if (dlibAllowed && detector.hasDlib()) {
        const Eigen::VectorXd ibug = detector.dlibLandmarks(bgr, face);
        if (ibug.size() == 2 * scheme23::kIbugPointCount) {
            out.shape = mapIbug68To23(ibug);
            out.method = "dlib";
            return out;
        }
    }
    if (method == AutoLandmarkMethod::Dlib)
        throw Error("dlib's shape predictor is not available (install libdlib-data)");
    if (fitter && method != AutoLandmarkMethod::Template) {
        out.shape = fitter->fit(bgr, initialShapeFromDetection(fitter->model(), face)).shape;
        out.method = "aam";
        return out;
    }
    out.shape = initialShapeFromDetection(templateShape(), face);
    out.method = "template";
    return out;
}

} // namespace lipsync
