#include "aam/AamModel.h"

#include "io/AtomicFile.h"
#include "util/Error.h"

#include <QCryptographicHash>
#include <QByteArray>

#include <cmath>
#include <cstring>
#include <type_traits>

namespace lipsync {

namespace {

constexpr char kMagic[8] = {'L', 'S', 'A', 'A', 'M', '\n', '\x1a', '\0'};
constexpr double kMargin = 2.0;
// The reference frames of real models are a few hundred pixels wide; a file claiming more is corrupt.
constexpr double kMaxReferenceFrame = 1024.0;

class Writer
{
public:
    void raw(const void *data, size_t size) { m_out.append(static_cast<const char *>(data), size); }
    void i32(int v) { raw(&v, sizeof v); }
    void f64(double v) { raw(&v, sizeof v); }
    void str(const std::string &s)
    {
        i32(int(s.size()));
        raw(s.data(), s.size());
    }
    void vec(const Eigen::VectorXd &v)
    {
        i32(int(v.size()));
        raw(v.data(), sizeof(double) * size_t(v.size()));
    }
    // A matrix stored as Scalar (double, or float for single-precision bases).
    template <class Scalar = double> void mat(const Eigen::MatrixXd &m)
    {
        i32(int(m.rows()));
        i32(int(m.cols()));
        if constexpr (std::is_same_v<Scalar, double>) {
            raw(m.data(), sizeof(double) * size_t(m.size()));
        } else {
            const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> stored = m.cast<Scalar>();
            raw(stored.data(), sizeof(Scalar) * size_t(stored.size()));
        }
    }
    template <class Matrix> void bytes(const Matrix &m)
    {
        i32(int(m.rows()));
        i32(int(m.cols()));
        raw(m.data(), size_t(m.size()));
    }
    std::string &out() { return m_out; }

private:
    std::string m_out;
};

class Reader
{
public:
    Reader(const std::string &data, const std::string &path) : m_data(data), m_path(path) {}
    void raw(void *out, size_t size)
    {
        if (size == 0) // an empty matrix has no data pointer: memcpy(nullptr, ..., 0) is undefined
            return;
        if (m_pos + size > m_data.size())
            throw Error("truncated AAM file", m_path);
        std::memcpy(out, m_data.data() + m_pos, size);
        m_pos += size;
    }
    int i32()
    {
        int v = 0;
        raw(&v, sizeof v);
        return v;
    }
    // A count of items of `itemBytes` each, checked against the bytes left before anything is
    // allocated: a damaged count is rejected at once instead of allocating up to the file's size.
    int count(const char *what, double itemBytes = 1)
    {
        const int v = i32();
        if (v < 0 || double(v) * itemBytes > double(remaining()))
            throw Error("corrupt AAM file (more " + std::string(what) + " than the file holds)", m_path, what);
        return v;
    }
    double f64()
    {
        double v = 0;
        raw(&v, sizeof v);
        return v;
    }
    std::string str(const char *what)
    {
        std::string s(size_t(count(what)), '\0');
        raw(s.data(), s.size());
        return s;
    }
    Eigen::VectorXd vec(const char *what)
    {
        Eigen::VectorXd v(count(what, sizeof(double)));
        raw(v.data(), sizeof(double) * size_t(v.size()));
        return v;
    }
    // A matrix stored as Scalar (double, or float for single-precision bases).
    template <class Scalar = double> Eigen::MatrixXd mat(const char *what)
    {
        const int r = count(what), c = count(what);
        if (double(r) * double(c) * sizeof(Scalar) > double(remaining()))
            throw Error("corrupt AAM file (more " + std::string(what) + " than the file holds)", m_path, what);
        Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> m(r, c);
        raw(m.data(), sizeof(Scalar) * size_t(m.size()));
        if constexpr (std::is_same_v<Scalar, double>)
            return m;
        else
            return m.template cast<double>();
    }
    Eigen::Matrix<std::int8_t, Eigen::Dynamic, Eigen::Dynamic> bytes(const char *what)
    {
        const int r = count(what), c = count(what);
        if (double(r) * double(c) > double(remaining()))
            throw Error("corrupt AAM file (more " + std::string(what) + " than the file holds)", m_path, what);
        Eigen::Matrix<std::int8_t, Eigen::Dynamic, Eigen::Dynamic> m(r, c);
        raw(m.data(), size_t(m.size()));
        return m;
    }
    bool atEnd() const { return m_pos == m_data.size(); }
    size_t remaining() const { return m_data.size() - m_pos; }

private:
    const std::string &m_data;
    const std::string &m_path;
    size_t m_pos = 0;
};

// A cheap necessary condition for the rasterised frame to have `pixels` pixels, checked before
// prepare() rasterises it: a convex region of area A and perimeter P holds more than A - P lattice
// points (a unit cell it covers whose centre lies outside touches its boundary, so such cells cover
// at most P/sqrt(2) of A), and the frame's pixels include those of every triangle. A damaged scale or vertex that blows a
// triangle up is rejected here instead of rasterising a frame of up to 1024 x 1024 pixels first.
bool trianglesFitPixelCount(const Eigen::VectorXd &reference, const std::vector<Triangle> &triangles,
                            Eigen::Index pixels)
{
    for (const Triangle &t : triangles) {
        const Eigen::Vector2d a = reference.segment<2>(2 * t[0]), b = reference.segment<2>(2 * t[1]),
                              c = reference.segment<2>(2 * t[2]);
        const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
        const double perimeter = (b - a).norm() + (c - b).norm() + (a - c).norm();
        if (area - perimeter > double(pixels))
            return false;
    }
    return true;
}

} // namespace

Similarity AamModel::referenceTransform(int level) const
{
    const double scale = referenceScale * levels.at(size_t(level)).scale;
    double minX = 1e300, minY = 1e300;
    for (int i = 0; i < pointCount(); ++i) {
        minX = std::min(minX, scale * meanShape[2 * i]);
        minY = std::min(minY, scale * meanShape[2 * i + 1]);
    }
    Similarity t;
    t.a = scale;
    t.tx = kMargin - minX;
    t.ty = kMargin - minY;
    return t;
}

Eigen::VectorXd AamModel::referenceShape(int level) const
{
    return referenceTransform(level).apply(meanShape);
}

void AamModel::prepare()
{
    m_warps.clear();
    for (int l = 0; l < int(levels.size()); ++l)
        m_warps.emplace_back(referenceShape(l), triangles);
}

Eigen::VectorXd AamModel::combinedFromParts(const Eigen::VectorXd &shapeParams,
                                            const Eigen::VectorXd &textureParams) const
{
    Eigen::VectorXd joint(shapeParams.size() + textureParams.size());
    joint << shapeWeight * shapeParams, textureParams;
    return combinedBasis.transpose() * joint;
}

void AamModel::partsFromCombined(const Eigen::VectorXd &combined, Eigen::VectorXd &shapeParams,
                                 Eigen::VectorXd &textureParams) const
{
    const Eigen::VectorXd joint = combinedBasis * combined;
    shapeParams = joint.head(shapeModes()) / shapeWeight;
    textureParams = joint.tail(textureModes());
}

std::string AamModel::serialise(bool withIdentifier) const
{
    Writer w;
    w.raw(kMagic, sizeof kMagic);
    int version = 1;
    if (singlePrecisionBases)
        version = 4;
    else if (exemplarCount() > 0)
        version = 3;
    else if (detectorRegression.size() > 0 || fitFeatures != AamFitFeatures::Grey)
        version = 2;
    w.i32(version);
    w.str(withIdentifier ? identifier : std::string());
    w.i32(trainingImages);
    w.vec(meanShape);
    w.mat(shapeBasis);
    w.vec(shapeVariances);
    w.i32(int(triangles.size()));
    for (const auto &t : triangles)
        for (int v : t)
            w.i32(v);
    w.f64(referenceScale);
    const auto basis = [&](const Eigen::MatrixXd &m) { version >= 4 ? w.mat<float>(m) : w.mat(m); };
    w.vec(textureMean);
    basis(textureBasis);
    w.vec(textureVariances);
    w.f64(meanTextureScale);
    w.f64(meanTextureOffset);
    w.f64(shapeWeight);
    w.mat(combinedBasis);
    w.vec(combinedVariances);
    w.i32(int(levels.size()));
    for (const auto &l : levels) {
        w.f64(l.scale);
        w.vec(l.mean);
        basis(l.basis);
        w.vec(l.variances);
    }
    w.vec(detectorShape);
    if (version >= 2) {
        w.mat(detectorRegression);
        w.vec(detectorKeypointMean);
        w.i32(int(fitFeatures));
    }
    if (version >= 3) {
        // Version 4 may have no exemplars (then three empty matrices).
        w.mat(exemplarParams);
        w.bytes(exemplarDetail);
        w.vec(exemplarScales);
    }
    return std::move(w.out());
}

bool AamModel::hasMagic(std::string_view firstBytes)
{
    return firstBytes.size() >= sizeof kMagic && std::memcmp(firstBytes.data(), kMagic, sizeof kMagic) == 0;
}

std::string AamModel::computeIdentifier() const
{
    const std::string bytes = serialise(false);
    const QByteArray hash = QCryptographicHash::hash(
        QByteArray::fromRawData(bytes.data(), qsizetype(bytes.size())), QCryptographicHash::Sha1);
    return "aam-" + hash.toHex().left(16).toStdString();
}

void AamModel::save(const std::string &path) const
{
    writeFileAtomically(path, serialise(true));
}

AamModel AamModel::load(const std::string &path)
{
    return fromBytes(readWholeFile(path), path);
}

AamModel AamModel::fromBytes(const std::string &data, const std::string &path)
{
    if (!hasMagic(data))
        throw Error("not an AAM model file (bad magic)", path);
    Reader r(data, path);
    char magic[sizeof kMagic];
    r.raw(magic, sizeof magic);
    const int version = r.i32();
    if (version < 1 || version > kFormatVersion)
        throw Error("unsupported AAM file version " + std::to_string(version) + " (expected 1 to "
                        + std::to_string(kFormatVersion) + ")",
                    path, "version");
    AamModel m;
    m.singlePrecisionBases = version >= 4;
    const auto basis = [&](const char *what) { return version >= 4 ? r.mat<float>(what) : r.mat(what); };
    m.identifier = r.str("identifier");
    m.trainingImages = r.i32();
    m.meanShape = r.vec("meanShape");
    m.shapeBasis = r.mat("shapeBasis");
    m.shapeVariances = r.vec("shapeVariances");
    const int nt = r.count("triangles", 3 * sizeof(int));
    const int np = m.pointCount();
    for (int i = 0; i < nt; ++i) {
        Triangle t{r.i32(), r.i32(), r.i32()};
        for (int v : t)
            if (v < 0 || v >= np)
                throw Error("triangle vertex out of range", path, "triangles");
        m.triangles.push_back(t);
    }
    m.referenceScale = r.f64();
    m.textureMean = r.vec("textureMean");
    m.textureBasis = basis("textureBasis");
    m.textureVariances = r.vec("textureVariances");
    m.meanTextureScale = r.f64();
    m.meanTextureOffset = r.f64();
    m.shapeWeight = r.f64();
    m.combinedBasis = r.mat("combinedBasis");
    m.combinedVariances = r.vec("combinedVariances");
    const int nl = r.count("levels", 3 * sizeof(double)); // scale and three sizes at least
    for (int i = 0; i < nl; ++i) {
        AamTextureLevel l;
        l.scale = r.f64();
        l.mean = r.vec("levels");
        l.basis = basis("levels");
        l.variances = r.vec("levels");
        m.levels.push_back(std::move(l));
    }
    m.detectorShape = r.vec("detectorShape");
    if (version >= 2) {
        m.detectorRegression = r.mat("detectorRegression");
        m.detectorKeypointMean = r.vec("detectorKeypointMean");
        const int features = r.i32();
        if (features != int(AamFitFeatures::Grey) && features != int(AamFitFeatures::GradientOrientation))
            throw Error("unknown fitting features " + std::to_string(features), path, "features");
        m.fitFeatures = AamFitFeatures(features);
    }
    if (version >= 3) {
        m.exemplarParams = r.mat("exemplarParams");
        m.exemplarDetail = r.bytes("exemplarDetail");
        m.exemplarScales = r.vec("exemplarScales");
    }
    if (!r.atEnd())
        throw Error("trailing data after the AAM model", path);
    // Consistency: sizes must agree or fitting would read out of bounds.
    bool ok = np >= 3 && m.shapeBasis.rows() == m.meanShape.size()
                    && m.shapeVariances.size() == m.shapeBasis.cols() && nt > 0 && nl > 0
                    && m.textureBasis.rows() == m.textureMean.size()
                    && m.textureVariances.size() == m.textureBasis.cols()
                    && m.combinedBasis.rows() == m.shapeModes() + m.textureModes()
                    && m.referenceScale > 0 && m.shapeWeight > 0
                    && (m.detectorShape.size() == 0 || m.detectorShape.size() == m.meanShape.size())
                    && (m.detectorRegression.size() == 0
                        || (m.detectorShape.size() > 0 && m.detectorRegression.rows() == m.meanShape.size()
                            && m.detectorRegression.cols() == 10 && m.detectorKeypointMean.size() == 10))
                    // Colour: 3 values per level-0 pixel; fitting: fitChannels() per pixel.
                    && m.textureMean.size() * m.fitChannels() == 3 * m.levels[0].mean.size()
                    && (m.exemplarCount() == 0
                        || (m.exemplarParams.rows() == m.combinedModes()
                            && m.exemplarDetail.rows() == m.textureMean.size()
                            && m.exemplarDetail.cols() == m.exemplarCount()
                            && m.exemplarScales.size() == m.exemplarCount() && m.exemplarParams.allFinite()
                            && m.exemplarScales.allFinite() && m.exemplarScales.minCoeff() >= 0))
                    && (version != 3 || m.exemplarCount() > 0);
    for (int l = 0; ok && l < nl; ++l) {
        const AamTextureLevel &level = m.levels[size_t(l)];
        ok = level.basis.rows() == level.mean.size() && level.variances.size() == level.basis.cols()
             && level.mean.size() % m.fitChannels() == 0;
    }
    if (!ok)
        throw Error("inconsistent AAM model (sizes disagree)", path);
    // prepare() rasterises each level's reference frame from these numbers: non-finite or huge
    // values would overflow the int frame size or allocate without bound.
    bool bounded = m.meanShape.allFinite() && std::isfinite(m.referenceScale) && std::isfinite(m.shapeWeight);
    for (int l = 0; bounded && l < nl; ++l) {
        const double scale = m.levels[size_t(l)].scale;
        bounded = std::isfinite(scale) && scale > 0;
        if (bounded) {
            const Eigen::VectorXd reference = m.referenceShape(l);
            bounded = reference.allFinite() && reference.maxCoeff() < kMaxReferenceFrame;
            if (bounded && !trianglesFitPixelCount(reference, m.triangles,
                                                    m.levels[size_t(l)].mean.size() / m.fitChannels()))
                throw Error("inconsistent AAM model (level texture size)", path);
        }
    }
    if (!bounded)
        throw Error("inconsistent AAM model (reference frame not finite or larger than "
                        + std::to_string(int(kMaxReferenceFrame)) + " pixels)",
                    path);
    // The identifier is a hash of the content (computeIdentifier): damaged numbers that still
    // parse would otherwise fit faces with garbage.
    if (m.identifier.rfind("aam-", 0) == 0 && m.identifier != m.computeIdentifier())
        throw Error("corrupt AAM file (the content does not match its identifier " + m.identifier + ")", path);
    m.prepare();
    if (m.textureMean.size() != 3 * m.warp(0).pixelCount())
        throw Error("inconsistent AAM model (texture size)", path);
    for (int l = 0; l < nl; ++l)
        if (m.levels[size_t(l)].mean.size() != m.fitChannels() * m.warp(l).pixelCount()
            || m.levels[size_t(l)].basis.rows() != m.fitChannels() * m.warp(l).pixelCount())
            throw Error("inconsistent AAM model (level texture size)", path);
    return m;
}

} // namespace lipsync
