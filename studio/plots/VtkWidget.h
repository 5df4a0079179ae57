#pragma once
// A QOpenGLWidget that hosts a vtkGenericOpenGLRenderWindow. Debian's VTK ships its Qt widget
// for Qt 5 only, so the studio carries this small adaptor (see docs in toolchain.md: Qt owns the
// GL context and the framebuffer; VTK renders into its own framebuffer, which paintGL blits into
// the widget's).
#include <QOpenGLWidget>

#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;

namespace lipsync::studio {

class VtkWidget : public QOpenGLWidget
{
    Q_OBJECT
public:
    explicit VtkWidget(QWidget *parent = nullptr);
    ~VtkWidget() override;

    vtkGenericOpenGLRenderWindow *renderWindow() const;
    vtkGenericRenderWindowInteractor *interactor() const;

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    void forwardMouse(QMouseEvent *event, unsigned long vtkEvent);
    void finalizeVtk();
    static void onVtkEvent(vtkObject *caller, unsigned long event, void *clientData, void *callData);

    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace lipsync::studio
