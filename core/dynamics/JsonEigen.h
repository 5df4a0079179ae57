#pragma once
// Eigen <-> JSON for model files. Doubles are written by Qt with the shortest representation
// that reads back to the same value, so save/load round trips are exact.
#include <QJsonArray>
#include <QJsonObject>

#include <Eigen/Core>

#include <string>

namespace lipsync::json {

QJsonArray fromVector(const Eigen::VectorXd &v);
QJsonArray fromMatrix(const Eigen::MatrixXd &m); // array of rows
// Throw lipsync::Error(file, field) when missing, not numeric, or of the wrong size
// (rows/cols < 0: any).
Eigen::VectorXd toVector(const QJsonObject &o, const char *field, Eigen::Index size,
                         const std::string &file);
Eigen::MatrixXd toMatrix(const QJsonObject &o, const char *field, Eigen::Index rows,
                         Eigen::Index cols, const std::string &file);
double toDouble(const QJsonObject &o, const char *field, const std::string &file);

} // namespace lipsync::json
