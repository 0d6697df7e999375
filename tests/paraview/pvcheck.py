# What the pvpython checks share: a failure line, and the datasets of a
# reader's (possibly nested) multiblock output.
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def leaves(data):
    """The datasets of a (possibly nested) multiblock, depth first."""
    if data is None:
        return []
    if data.IsA("vtkMultiBlockDataSet"):
        out = []
        for i in range(data.GetNumberOfBlocks()):
            out += leaves(data.GetBlock(i))
        return out
    return [data]
