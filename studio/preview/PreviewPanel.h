#pragma once
// Preview & compare: the recorded video of the current sequence, played at its frame rate.
// Generated faces will be shown beside it once the dynamic models can generate them.
#include <QWidget>

class QLabel;
class QImage;

namespace lipsync::studio {

class FrameView;
struct StudioActions;

class PreviewPanel : public QWidget
{
    Q_OBJECT
public:
    PreviewPanel(const StudioActions &actions, QWidget *parent = nullptr);

    void setFrame(const QImage &image, const QString &caption);
    void setPlaceholderText(const QString &text);
    FrameView *view() const { return m_view; }

private:
    FrameView *m_view;
    QLabel *m_caption;
};

} // namespace lipsync::studio
