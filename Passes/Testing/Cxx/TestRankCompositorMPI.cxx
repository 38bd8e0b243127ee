// vtkStylizeRankCompositor on the ranks of an MPI run (mpiexec -n 2): process 1's part reaches
// process 0 nearest by depth, process 0's depth reaches process 1.
#include "RankCompositorChecks.h"

#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstdio>

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkObject::GlobalWarningDisplayOff(); // the refused part reports an error by design
  int failures = rankcheck::Run(controller);
  int total = 0;
  controller->AllReduce(&failures, &total, 1, vtkCommunicator::SUM_OP);
  if (controller->GetLocalProcessId() == 0)
  {
    std::printf("%d processes, %d failures\n", controller->GetNumberOfProcesses(), total);
  }
  controller->Finalize();
  return total == 0 ? 0 : 1;
}
