#include "dynamics/JsonEigen.h"

#include "util/Error.h"

#include <cmath>

namespace lipsync::json {

QJsonArray fromVector(const Eigen::VectorXd &v)
{
    QJsonArray a;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        a.append(v[i]);
    return a;
}

QJsonArray fromMatrix(const Eigen::MatrixXd &m)
{
    QJsonArray rows;
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        rows.append(fromVector(m.row(r).transpose()));
    return rows;
}

namespace {
Eigen::VectorXd parseArray(const QJsonValue &value, Eigen::Index size, const std::string &file,
                           const std::string &field)
{
    if (!value.isArray())
        throw Error("missing or not an array", file, field);
    const QJsonArray a = value.toArray();
    if (size >= 0 && a.size() != size)
        throw Error("has " + std::to_string(a.size()) + " values, expected " + std::to_string(size),
                    file, field);
    Eigen::VectorXd v(a.size());
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (!a[i].isDouble())
            throw Error("value " + std::to_string(i) + " is not a number", file, field);
        v[Eigen::Index(i)] = a[i].toDouble();
        if (!std::isfinite(v[Eigen::Index(i)]))
            throw Error("value " + std::to_string(i) + " is not finite", file, field);
    }
    return v;
}
} // namespace

Eigen::VectorXd toVector(const QJsonObject &o, const char *field, Eigen::Index size,
                         const std::string &file)
{
    return parseArray(o.value(QLatin1String(field)), size, file, field);
}

Eigen::MatrixXd toMatrix(const QJsonObject &o, const char *field, Eigen::Index rows,
                         Eigen::Index cols, const std::string &file)
{
    const QJsonValue value = o.value(QLatin1String(field));
    if (!value.isArray())
        throw Error("missing or not an array", file, field);
    const QJsonArray a = value.toArray();
    if (rows >= 0 && a.size() != rows)
        throw Error("has " + std::to_string(a.size()) + " rows, expected " + std::to_string(rows),
                    file, field);
    Eigen::MatrixXd m;
    for (qsizetype r = 0; r < a.size(); ++r) {
        const Eigen::VectorXd row = parseArray(a[r], cols, file,
                                               std::string(field) + "[" + std::to_string(r) + "]");
        if (r == 0)
            m.resize(a.size(), row.size());
        else if (row.size() != m.cols())
            throw Error("ragged rows", file, field);
        m.row(Eigen::Index(r)) = row.transpose();
    }
    if (a.isEmpty())
        m.resize(0, cols < 0 ? 0 : cols);
    return m;
}

double toDouble(const QJsonObject &o, const char *field, const std::string &file)
{
    const QJsonValue v = o.value(QLatin1String(field));
    if (!v.isDouble())
        throw Error("missing or not a number", file, field);
    return v.toDouble();
}

} // namespace lipsync::json
