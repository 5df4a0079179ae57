#include "aam/DlibFaceModels.h"

#ifdef LIPSYNC_HAVE_DLIB
#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/opencv/cv_image.h>
#endif

#include <cmath>

namespace lipsync {

struct DlibFaceModels::Impl
{
#ifdef LIPSYNC_HAVE_DLIB
    std::unique_ptr<dlib::shape_predictor> predictor;
    std::unique_ptr<dlib::frontal_face_detector> hog;
#endif
};

DlibFaceModels::DlibFaceModels() : m_impl(std::make_unique<Impl>()) {}

DlibFaceModels::~DlibFaceModels() = default;

bool DlibFaceModels::available()
{
#ifdef LIPSYNC_HAVE_DLIB
    return true;
#else
    return false;
#endif
}

bool DlibFaceModels::loadPredictor(const std::string &path)
{
#ifdef LIPSYNC_HAVE_DLIB
    try {
        auto predictor = std::make_unique<dlib::shape_predictor>();
        dlib::deserialize(path) >> *predictor;
        m_impl->predictor = std::move(predictor);
        return true;
    } catch (const std::exception &) {
        return false;
    }
#else
    (void)path;
    return false;
#endif
}

bool DlibFaceModels::hasPredictor() const
{
#ifdef LIPSYNC_HAVE_DLIB
    return m_impl->predictor != nullptr;
#else
    return false;
#endif
}

std::vector<cv::Rect2d> DlibFaceModels::hogFaces(const cv::Mat &grey)
{
    std::vector<cv::Rect2d> out;
#ifdef LIPSYNC_HAVE_DLIB
    if (grey.empty() || grey.type() != CV_8UC1)
        return out;
    if (!m_impl->hog)
        m_impl->hog = std::make_unique<dlib::frontal_face_detector>(dlib::get_frontal_face_detector());
    dlib::cv_image<unsigned char> image(grey);
    for (const dlib::rectangle &r : (*m_impl->hog)(image))
        out.emplace_back(double(r.left()), double(r.top()), double(r.width()), double(r.height()));
#else
    (void)grey;
#endif
    return out;
}

Eigen::VectorXd DlibFaceModels::landmarks68(const cv::Mat &grey, const cv::Rect2d &b) const
{
#ifdef LIPSYNC_HAVE_DLIB
    if (!m_impl->predictor || grey.empty() || grey.type() != CV_8UC1)
        return {};
    dlib::cv_image<unsigned char> image(grey);
    const dlib::rectangle rect(long(std::lround(b.x)), long(std::lround(b.y)),
                               long(std::lround(b.x + b.width)), long(std::lround(b.y + b.height)));
    const dlib::full_object_detection shape = (*m_impl->predictor)(image, rect);
    if (shape.num_parts() != 68)
        return {};
    Eigen::VectorXd out(136);
    for (unsigned long i = 0; i < 68; ++i) {
        out[2 * long(i)] = double(shape.part(i).x());
        out[2 * long(i) + 1] = double(shape.part(i).y());
    }
    return out;
#else
    (void)grey;
    (void)b;
    return {};
#endif
}

} // namespace lipsync
