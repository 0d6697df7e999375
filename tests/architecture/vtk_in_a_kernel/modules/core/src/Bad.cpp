// A kernel source that includes VTK: what the check must refuse.
#include <vtkPolyData.h>
