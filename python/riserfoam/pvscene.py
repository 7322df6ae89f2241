"""The pieces of the project's ParaView pictures (pvbatch scripts only: it
imports paraview.simple): a white render view, the riser wall drawn faint,
and a field shown through the Viridis colour map with its bar.

SPDX-License-Identifier: GPL-3.0-or-later
"""
from paraview.simple import GetActiveViewOrCreate, GetColorTransferFunction, GetScalarBar, Show


def white_view(width, height):
    """the render view, white, of the given size in pixels"""
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:      # ParaView before 5.10
        pass
    return view


def faint_wall(source, view):
    """the riser wall: a source shown translucent blue-grey, uncoloured"""
    shown = Show(source, view)
    shown.Opacity = 0.15
    shown.DiffuseColor = [0.35, 0.45, 0.6]
    shown.AmbientColor = [0.35, 0.45, 0.6]
    shown.ColorArrayName = ["POINTS", ""]
    return shown


def coloured(source, view, field, title):
    """a source shown coloured by its point field through Viridis, with a
    scalar bar of the title; returns the colour map"""
    shown = Show(source, view)
    shown.ColorArrayName = ["POINTS", field]
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    shown.LookupTable = lut
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    return lut
