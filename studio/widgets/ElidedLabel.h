#pragma once
// A one-line label that never asks for more width than it is given: text too long for it ends in
// "…", and the whole text is always its tooltip. For status lines and details in narrow panels, in every
// language (German runs a third longer than English).
#include <QFrame>
#include <QString>

namespace lipsync::studio {

class ElidedLabel : public QFrame
{
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget *parent = nullptr);

    QString text() const { return m_text; }
    void setText(const QString &text);
    void clear() { setText(QString()); }
    // The text as drawn: elided to the width, or whole.
    QString shownText() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QString m_text;
};

} // namespace lipsync::studio
