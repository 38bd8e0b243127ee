// vtkStylizeRankCompositor on one process (vtkDummyController): merging, ties, rectangles and
// the collective calls' single-process behaviour. TestRankCompositorMPI runs the same checks
// on 2 ranks.
#include "RankCompositorChecks.h"

#include "vtkDummyController.h"
#include "vtkNew.h"
#include "vtkObject.h"

int TestRankCompositor(int, char*[])
{
  vtkNew<vtkDummyController> controller;
  vtkObject::GlobalWarningDisplayOff(); // the refused part reports an error by design
  const int failures = rankcheck::Run(controller);
  vtkObject::GlobalWarningDisplayOn();
  return failures == 0 ? 0 : 1;
}
