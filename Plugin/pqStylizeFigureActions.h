/**
 * @class   pqStylizeFigureActions
 * @brief   The GUI's File menu entries for the VTK Stylize view: "Export Stylized Figure..."
 *          (SVG or PDF) and "Save Stylized Orbit..." (PNG frames, GIF or MP4).
 *
 * Each entry asks for a file in ParaView's file dialog (on the active server); the orbit then
 * asks for its options in a dialog built from stylize_paraview.ORBIT_OPTIONS, with the defaults
 * of stylize_paraview.SaveStylizedOrbit. Both then call stylize_paraview's Python functions
 * (SaveStylizedFigure, SaveStylizedOrbit) on the active view, so that the GUI and Python write
 * the same files from one implementation. A failure (the style None, a bad extension, a file
 * that cannot be written) is shown in a message box with the function's line. The entries are
 * enabled only while the active view is a VTK Stylize view.
 *
 * Registered by paraview_plugin_add_action_group with the group name "MenuBar/File": ParaView
 * inserts the actions above File > Exit.
 */
#ifndef pqStylizeFigureActions_h
#define pqStylizeFigureActions_h

#include <QActionGroup>

class pqStylizeFigureActions : public QActionGroup
{
  Q_OBJECT

public:
  explicit pqStylizeFigureActions(QObject* parent);
  ~pqStylizeFigureActions() override = default;

private Q_SLOTS:
  void updateEnabled();
  void exportFigure();
  void saveOrbit();

private:
  QAction* FigureAction;
  QAction* OrbitAction;
};

#endif
