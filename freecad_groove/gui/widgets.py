"""Small Qt helpers the Groove task panel's pages are built from: loading a
page's .ui form, finding its widgets, filling and reading combo boxes,
marking invalid fields, showing the engine's message, and the quantity fields
bound to op properties. Warnings (what the op cannot do as programmed but
does anyway) show in amber under the error line and mark their fields in
amber; they never block OK.

GUI layer: Qt only through FreeCAD's ``PySide`` shim. Widgets and FreeCAD
objects are typed ``object``.
"""

import os
import re

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from . import PANELS, qt_wrappers

translate = FreeCAD.Qt.translate
CONTEXT = "FreeCADGroove"

INVALID_STYLE = "border: 2px solid #d00000;"
ERROR_STYLE = "color: #b00000;"
INVALID_PROPERTY = "grooveInvalid"  # the Qt property that marks a field invalid
ERROR_LABEL = "errorLabel"  # object name of the label the engine's message shows in
WARNED_STYLE = "border: 2px solid #e08000;"  # amber: the op runs, not as programmed
WARNING_STYLE = "color: #b35c00;"
WARNED_PROPERTY = "grooveWarned"  # the Qt property that marks a field a warning names
WARNING_LABEL = "warningLabel"  # object name of the label the warnings show in


def load_form(name: str) -> object:
    """A page's form from resources/panels/<name> (a .ui file), made to fit narrow docks."""
    form = FreeCADGui.PySideUic.loadUi(os.path.join(PANELS, name))
    qt_wrappers.drop_stale(form)
    fit_narrow_docks(form)
    return form


FIELD_SAMPLE = "00.00 mm"  # a field always shows this much text whole
FIELD_FRAME = 30  # px: a spin box's frame, margins and up/down buttons beside its text (when its style cannot say)
EDIT_MARGINS = 6  # px: a line edit's margins beside its text and the cursor
BUTTON_PADDING = 16  # px: a push button's frame and margins beside its text
COMBO_WIDE = 110  # px: a combo box wider than this (a tool controller's name) may elide
COMBO_CHARS = 6  # its own width then, in characters (8: a tool controller's row was 227 px in 1.0's 218)
FORM_ROW = 180  # px: a form row in a group box of 1.0's default combo view
WRAP_WIDER_THAN = 200  # px: a label whose one line is wider than this wraps


def fit_narrow_docks(form: object) -> None:
    """Let a page fit the task dock's default width (FreeCAD 1.0's combo
    view is the narrowest). Idempotent: the panel runs it again on FreeCAD's
    own pages once they are filled.

    A spin box's size hint is the text of its largest value with the unit
    (wider than any real value), so wide spin boxes take the width their row
    leaves, but never less than FIELD_SAMPLE; a form's labels go above its
    fields when a row does not fit 1.0's dock, and two fields side by side (a
    corner's kind and size) one above the other; long one-line labels wrap; push buttons may
    shrink to their text (the style's 80 px minimum makes a row of three wider
    than the dock)."""
    for box in form.findChildren(QtGui.QAbstractSpinBox):
        least = text_width(box, FIELD_SAMPLE) + spin_frame(box)
        if box.sizeHint().width() > least or box.sizePolicy().horizontalPolicy() == QtGui.QSizePolicy.Ignored:
            box.setSizePolicy(QtGui.QSizePolicy.Ignored, box.sizePolicy().verticalPolicy())
        box.setMinimumWidth(max(least, box.minimumWidth()))  # never less (1.0's size hint forgets its padding)
    for layout in form.findChildren(QtGui.QHBoxLayout):  # a corner's kind and size: one above the other
        if layout.minimumSize().width() > FORM_ROW:
            layout.setDirection(QtGui.QBoxLayout.TopToBottom)
    for layout in form.findChildren(QtGui.QFormLayout):
        choose_form_rows(layout)
    for label in form.findChildren(QtGui.QLabel):
        if label.text() and not label.wordWrap() and label.sizeHint().width() > WRAP_WIDER_THAN:
            label.setWordWrap(True)
    for button in form.findChildren(QtGui.QPushButton):
        needed = text_width(button, button.text()) + BUTTON_PADDING
        if not button.icon().isNull():
            needed += button.iconSize().width() + BUTTON_PADDING // 2
        if button.text() and needed < button.sizeHint().width():
            button.setMinimumWidth(needed)
    for combo in form.findChildren(QtGui.QComboBox):
        if combo.sizeHint().width() > COMBO_WIDE:
            fit_combo(combo)
    for view in form.findChildren(QtGui.QAbstractItemView):  # FreeCAD's face list would stay 256 px wide
        view.setSizePolicy(QtGui.QSizePolicy.Expanding, view.sizePolicy().verticalPolicy())


def spin_frame(box: object) -> int:
    """The px of a spin box beside its text: its frame and buttons as its style draws them, the line edit's 2 px
    each side, and the padding its style sheet keeps (edit_padding); FIELD_FRAME when the style cannot say."""
    try:
        option = QtGui.QStyleOptionSpinBox()
        option.initFrom(box)
        option.rect = QtCore.QRect(0, 0, 200, max(box.sizeHint().height(), 20))
        option.frame = box.hasFrame()
        option.buttonSymbols = box.buttonSymbols()
        option.subControls = QtGui.QStyle.SC_SpinBoxFrame | QtGui.QStyle.SC_SpinBoxEditField | \
            QtGui.QStyle.SC_SpinBoxUp | QtGui.QStyle.SC_SpinBoxDown
        field = box.style().subControlRect(QtGui.QStyle.CC_SpinBox, option, QtGui.QStyle.SC_SpinBoxEditField, box)
        frame = 200 - field.width() + EDIT_MARGINS
    except Exception:  # noqa: BLE001 - a style or binding that cannot answer: the measured default
        frame = FIELD_FRAME
    return frame + edit_padding(box)


def edit_padding(box: object) -> int:
    """The px a spin box's line edit keeps free right of its text by its style sheet (FreeCAD 1.0's quantity
    fields: 15 px for the expression icon, ``QLineEdit { padding-right: 15px }``), 0 for none."""
    edit = box.findChild(QtGui.QLineEdit)
    found = re.search(r"padding-right:\s*(\d+)px", edit.styleSheet()) if edit is not None else None
    return int(found.group(1)) if found else 0


def fit_combo(combo: object) -> None:
    """A combo box with long texts (a tool controller's name) as wide as its
    row allows: its own width is that of COMBO_CHARS characters at most
    (longer texts are elided in the box, whole in its list)."""
    longest = max([len(combo.itemText(i)) for i in range(combo.count())] + [1])
    combo.setMinimumContentsLength(min(longest, COMBO_CHARS))
    combo.setSizeAdjustPolicy(QtGui.QComboBox.AdjustToMinimumContentsLengthWithIcon)
    combo.setSizePolicy(QtGui.QSizePolicy.Expanding, combo.sizePolicy().verticalPolicy())


def choose_form_rows(layout: object) -> None:
    """A form's rows side by side (label, field) where both fit in FORM_ROW
    px, else every label above its field. Chosen once, not as the dock
    resizes: Qt's WrapLongRows leaves a field it moved under its label where
    the wider layout put it, cut off at the right, and wrapping labels get
    squeezed letter by letter. A form whose .ui asks for WrapAllRows keeps it."""
    if layout.rowWrapPolicy() == QtGui.QFormLayout.WrapAllRows:
        return
    # The widgets and inner layouts by their place, not layout.itemAt: a QLayoutItem is no QObject, and PySide
    # could hand back a stale wrapper left at its address by a deleted item (qt_wrappers).
    labels = fields = 0
    parent = layout.parentWidget()
    # The parent's own children only (a layout's widgets are; their inner editors are not), and only wrappers
    # that still claim a widget: FreeCAD 1.0 once handed out, for a child of a new form, a wrapper saying its
    # object was gone (RuntimeError building the Plunge grind form), and 1.1 crashed at the same place.
    children = parent.children() if parent is not None else []
    places = [(layout.getWidgetPosition(widget), widget.sizeHint().width(), _least_width(widget))
              for widget in children if isinstance(widget, QtGui.QWidget) and qt_wrappers.shiboken.isValid(widget)]
    places += [(layout.getLayoutPosition(inner), inner.sizeHint().width(), inner.minimumSize().width())
               for inner in layout.findChildren(QtGui.QLayout)]
    for (row, role), hint, least in places:
        if row < 0:
            continue  # not in this layout (the role is then not set)
        if role == QtGui.QFormLayout.LabelRole:
            labels = max(labels, hint)
        elif role == QtGui.QFormLayout.FieldRole:
            fields = max(fields, least)
    side_by_side = labels + max(layout.horizontalSpacing(), 6) + fields <= FORM_ROW
    layout.setRowWrapPolicy(QtGui.QFormLayout.DontWrapRows if side_by_side else QtGui.QFormLayout.WrapAllRows)


def _least_width(widget: object) -> int:
    """The width a layout gives a widget at the least (QWidgetItem.minimumSize: its minimum size, else its
    minimum size hint)."""
    return widget.minimumWidth() or widget.minimumSizeHint().width()


def text_width(widget: object, text: str) -> int:
    """Width in px of ``text`` in the widget's font."""
    metrics = widget.fontMetrics()
    if hasattr(metrics, "horizontalAdvance"):
        return metrics.horizontalAdvance(text)
    return metrics.width(text)


def child(form: object, name: str) -> object:
    """A form's widget by object name (not getattr: "width" is also QWidget.width())."""
    return form.findChild(QtCore.QObject, name)


def svg_pixmap(path: str, width: int, height: int) -> object:
    """An SVG drawn with QtSvg (FreeCAD 1.1's Qt has no SVG image plugin for QIcon)."""
    from PySide import QtSvg

    pixmap = QtGui.QPixmap(width, height)
    pixmap.fill(QtCore.Qt.transparent)
    painter = QtGui.QPainter(pixmap)
    QtSvg.QSvgRenderer(path).render(painter)
    painter.end()
    return pixmap


class ScaledPicture(QtCore.QObject):
    """Draws an SVG into a QLabel at the label's width, at most ``width`` x
    ``height`` px and keeping that ratio: the picture never sets the page's
    width and, in a narrow dock, shrinks instead of losing its sides."""

    def __init__(self, label: object, path: str, width: int, height: int):
        super().__init__(label)
        self.label, self.path, self.size, self.drawn = label, path, (width, height), None
        label.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Fixed)
        label.setMinimumSize(0, 0)
        label.setAlignment(QtCore.Qt.AlignCenter)
        label.installEventFilter(self)
        self.draw(width)

    def eventFilter(self, watched: object, event: object) -> bool:
        if not isinstance(event, QtCore.QEvent):
            # PySide handed the event out through a wrapper of a deleted object once at its address (FreeCAD 1.0
            # segfaulted reading its type): read nothing of it, and forget the wrapper so the next one is right
            qt_wrappers.forget([event])
            return False
        if event.type() == QtCore.QEvent.Resize:
            self.draw(self.label.width())  # the label this filter watches, through the wrapper it holds
        return False

    def draw(self, available: int) -> None:
        """Render the picture as wide as ``available`` px allow (no change: nothing to do)."""
        width = max(1, min(int(available), self.size[0]))
        if width == self.drawn:
            return
        self.drawn = width
        height = max(1, round(width * self.size[1] / self.size[0]))
        self.label.setPixmap(svg_pixmap(self.path, width, height))
        self.label.setFixedHeight(height)


def coalescing_timer(delay_ms: int, slot: object) -> object:
    """A single-shot timer calling slot() ``delay_ms`` after its last start(): the signals of one edit make one
    call. No parent: it must outlive the form, which Cancel may delete first."""
    timer = QtCore.QTimer()
    timer.setSingleShot(True)
    timer.setInterval(delay_ms)
    timer.timeout.connect(slot)
    return timer


def fill_combo(combo: object, texts: dict) -> None:
    """Fill a combo box from {stored value: text shown (translated here)}."""
    combo.blockSignals(True)
    combo.clear()
    for value, text in texts.items():
        combo.addItem(translate(CONTEXT, text), value)
    combo.blockSignals(False)


def select_data(combo: object, value: str) -> None:
    """Show the combo box entry whose stored value is ``value``, without a signal."""
    combo.blockSignals(True)
    index = combo.findData(value)
    if index >= 0:
        combo.setCurrentIndex(index)
    combo.blockSignals(False)


def connect_changed(widget: object, slot: object) -> None:
    """Call slot() whenever the user changes the widget's value."""
    if isinstance(widget, QtGui.QComboBox):
        widget.currentIndexChanged.connect(lambda *_a: slot())
    else:
        widget.valueChanged.connect(lambda *_a: slot())


def _mark(widget: object, prop: str, on: bool) -> None:
    """Set the Qt property ``prop`` of a field; its frame follows: red while
    invalid, amber while only warned, none otherwise."""
    if widget is None or (widget.property(prop) is True) == bool(on):
        return
    widget.setProperty(prop, bool(on))
    if widget.property(INVALID_PROPERTY) is True:
        widget.setStyleSheet(INVALID_STYLE)
    else:
        widget.setStyleSheet(WARNED_STYLE if widget.property(WARNED_PROPERTY) is True else "")


def mark_invalid(widget: object, invalid: bool) -> None:
    """Frame a field red while its value is what makes the groove invalid."""
    _mark(widget, INVALID_PROPERTY, invalid)


def mark_warned(widget: object, warned: bool) -> None:
    """Frame a field amber while a warning names it (red wins while it is also invalid)."""
    _mark(widget, WARNED_PROPERTY, warned)


def _show(label: object, message: object, style: str) -> None:
    if label is None:
        return
    label.setText(message or "")
    label.setStyleSheet(style)
    label.setVisible(bool(message))


def show_error(label: object, message: object) -> None:
    """Show ``message`` in an error label, or hide the label (message None or "")."""
    _show(label, message, ERROR_STYLE)


def show_warnings(label: object, lines: list) -> None:
    """Show the warning ``lines`` (the engine's texts), one a line, in a
    warning label, or hide the label when there are none."""
    text = "\n".join(translate(CONTEXT, "Warning: {0}").format(line) for line in lines)
    _show(label, text, WARNING_STYLE)


def add_to_layout(layout: object, widget: object) -> None:
    """Add a widget at the end of a layout (a new full-width row of a grid)."""
    if isinstance(layout, QtGui.QGridLayout):
        layout.addWidget(widget, layout.rowCount(), 0, 1, max(1, layout.columnCount()))
    else:
        layout.addWidget(widget)


def _new_label(form: object, name: str) -> object:
    label = QtGui.QLabel(form)
    label.setObjectName(name)
    label.setWordWrap(True)
    return label


def add_label(form: object, name: str) -> object:
    """A word-wrapping label named ``name`` at the end of a form's layout."""
    label = _new_label(form, name)
    add_to_layout(form.layout(), label)
    return label


def add_error_label(form: object) -> object:
    """The label the engine's message shows in (objectName errorLabel) and,
    under it, the warning label (warningLabel), hidden while all is well."""
    label = _new_label(form, ERROR_LABEL)
    label.setVisible(False)
    add_to_layout(form.layout(), label)
    add_to_layout(form.layout(), new_warning_label(form))
    return label


def new_warning_label(form: object) -> object:
    """A hidden label for the warnings (objectName warningLabel), not yet in a layout."""
    label = _new_label(form, WARNING_LABEL)
    label.setVisible(False)
    return label


FIELD_MAX_DECIMALS = 6  # a model's values carry 6 decimals (cycle93_recognize.VALUE_DECIMALS)


def field_decimals(value: float, least: int) -> int:
    """The fewest decimals, at least ``least``, that show ``value`` exactly (at most FIELD_MAX_DECIMALS)."""
    for digits in range(least, FIELD_MAX_DECIMALS):
        if abs(round(value, digits) - value) <= 1e-12 * max(1.0, abs(value)):
            return digits
    return max(least, FIELD_MAX_DECIMALS)


SHOWN_VALUE = "grooveShownValue"  # the Qt property holding the exact value show_quantity put in a field
SHOWN_TEXT = "grooveShownText"  # ... and the text the field showed for it


def show_quantity(widget: object, value: float) -> None:
    """Show ``value`` (in the field's unit) in a Gui::QuantitySpinBox with as many decimals as it has. Its
    rawValue keeps only the decimals shown (the user's preference, 2 by default; in the unit schema's unit:
    5 mm in US customary shows 0.20", rawValue 5.08 mm), so the exact value and the text shown for it are kept
    on the field: quantity_value gives the value, not its display, until the user types."""
    quantity = FreeCAD.Units.Quantity(float(value), widget.property("value").Unit)
    number_format = dict(quantity.Format)
    number_format["Precision"] = field_decimals(float(value), int(number_format["Precision"]))
    quantity.Format = number_format
    widget.setProperty("value", quantity)
    widget.setProperty(SHOWN_VALUE, float(value))
    widget.setProperty(SHOWN_TEXT, widget.text())


def quantity_value(widget: object) -> float:
    """A quantity field's value (mm, degrees): the exact value show_quantity showed while the field still shows
    the text it showed for it (a value read from the model, the op's own: never its rounded display, written
    back on OK as a change); otherwise what the user typed."""
    shown = widget.property(SHOWN_VALUE)
    if shown is not None and widget.text() == widget.property(SHOWN_TEXT):
        return float(shown)
    return float(widget.property("rawValue"))


class QuantityFields:
    """Quantity fields (Gui::QuantitySpinBox, unit set in the .ui) for op
    properties. Not CAM's PathGuiUtil.QuantitySpinBox: that one resets a field
    from its property whenever the field gets focus, which would drop a value
    typed earlier, since this panel writes to the op only on OK or Apply.

    ``pairs``: ((widget name, op property), ...)."""

    def __init__(self, form: object, pairs: tuple):
        self.widgets = {prop: child(form, name) for name, prop in pairs}

    def set_from(self, obj: object) -> None:
        """Show the op's values (no change signals)."""
        for prop, widget in self.widgets.items():
            widget.blockSignals(True)
            show_quantity(widget, getattr(obj, prop).Value)
            widget.blockSignals(False)

    def write_to(self, obj: object) -> None:
        """Write the values shown into the op (only those that differ)."""
        for prop, value in self.values().items():
            if abs(getattr(obj, prop).Value - value) > 1e-12:
                setattr(obj, prop, value)

    def values(self) -> dict:
        """{property: value in mm or degrees} as the fields show them now."""
        return {prop: quantity_value(widget) for prop, widget in self.widgets.items()}
