<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>About</name>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="166" />
        <source>About Carom</source>
        <translation>О программе Carom</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="169" />
        <source>Carom %1</source>
        <translation>Carom %1</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="172" />
        <source>A sandbox and scene editor for collision physics: balls, planes and cylinders under gravity, solved exactly or in steps.</source>
        <translation>Песочница и редактор сцен для физики столкновений: шары, плоскости и цилиндры под действием гравитации, рассчитанные точно или по шагам.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="177" />
        <source>Qt version %1</source>
        <translation>Версия Qt %1</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="178" />
        <source>Released under the MIT licence.</source>
        <translation>Распространяется по лицензии MIT.</translation>
    </message>
</context>
<context>
    <name>Language</name>
    <message>
        <location filename="../ui/language.cpp" line="36" />
        <source>System Default</source>
        <translation>Как в системе</translation>
    </message>
</context>
<context>
    <name>NumberText</name>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="43" />
        <source>“%1” is out of range</source>
        <translation>«%1» вне допустимого диапазона</translation>
    </message>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="45" />
        <source>“%1” is not a number</source>
        <translation>«%1» — не число</translation>
    </message>
</context>
<context>
    <name>ObjectRef</name>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="12" />
        <source>Plane</source>
        <translation>Плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="14" />
        <source>Cylinder</source>
        <translation>Цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="10" />
        <source>Ball</source>
        <translation>Шар</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="12" />
        <source>Planes</source>
        <translation>Плоскости</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="14" />
        <source>Cylinders</source>
        <translation>Цилиндры</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="10" />
        <source>Balls</source>
        <translation>Шары</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="67" />
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="17" />
        <source>Box</source>
        <translation>Ящик</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_kinds.cpp" line="17" />
        <source>Boxes</source>
        <translation>Ящики</translation>
    </message>
</context>
<context>
    <name>ValidationText</name>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="104" />
        <source>Penetration tolerance</source>
        <translation>Допуск проникновения</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="170" />
        <source>%1 would be %2 behind the surface of %3</source>
        <translation>%1 оказался бы на %2 за поверхностью объекта %3</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="173" />
        <source>%1 would overlap %2 by %3</source>
        <translation>%1 и %2 перекрывались бы на %3</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="177" />
        <source>%1: at most %2 in a scene (this would make %3)</source>
        <translation>%1: не больше %2 в сцене (было бы %3)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="184" />
        <source>%1 of %2</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="189" />
        <source>%1 must be a finite number</source>
        <translation>%1: нужно конечное число</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="191" />
        <source>%1 must lie within ±%2 (got %3)</source>
        <translation>%1: значение должно быть в пределах ±%2 (получено %3)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="195" />
        <source>%1 must be above zero (got %2)</source>
        <translation>%1: значение должно быть больше нуля (получено %2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="198" />
        <source>%1 must be at least %2 (got %3)</source>
        <translation>%1: значение должно быть не меньше %2 (получено %3)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="201" />
        <source>%1 must be between %2 and %3 (got %4)</source>
        <translation>%1: значение должно быть от %2 до %3 (получено %4)</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="205" />
        <source>%1 must not be zero: it gives a direction</source>
        <translation>%1: вектор не может быть нулевым, он задаёт направление</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/validation_text.cpp" line="209" />
        <source>%1 must be at most %n characters long (got %2)</source>
        <translation>
            <numerusform>%1: не длиннее %n символа (получено %2)</numerusform>
            <numerusform>%1: не длиннее %n символов (получено %2)</numerusform>
            <numerusform>%1: не длиннее %n символов (получено %2)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="214" />
        <source>%1 must be empty or a colour such as #ff8000 (got “%2”)</source>
        <translation>%1: нужно оставить пустым или указать цвет вида #ff8000 (получено «%2»)</translation>
    </message>
</context>
<context>
    <name>carom::editor::CylinderLengthField</name>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="35" />
        <source>Length (m):</source>
        <translation>Длина (м):</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="36" />
        <source>infinite</source>
        <translation>бесконечный</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="37" />
        <source>The length of the cylinders Add Cylinder places; empty: infinite</source>
        <translation>Длина цилиндров, которые ставит «Добавить цилиндр»; пусто: бесконечные</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="57" />
        <source>Cylinder length: %1</source>
        <translation>Длина цилиндра: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/cylinder_length_field.cpp" line="59" />
        <source>Cylinder length: must be a positive number (got %1)</source>
        <translation>Длина цилиндра: должна быть положительным числом (введено: %1)</translation>
    </message>
</context>
<context>
    <name>carom::editor::EditorTools</name>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="82" />
        <source>Turn Plane</source>
        <translation>Повернуть плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="92" />
        <source>Resize Cylinder</source>
        <translation>Изменить длину цилиндра</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="96" />
        <source>Turn Cylinder</source>
        <translation>Повернуть цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="76" />
        <source>Change Velocity</source>
        <translation>Изменить скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="364" />
        <source>Move</source>
        <translation>Переместить</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="445" />
        <source>Click on a surface or on the ground to place an object.</source>
        <translation>Щёлкните по поверхности или по земле, чтобы поставить объект.</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="467" />
        <source>Add Ball</source>
        <translation>Добавить шар</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="472" />
        <source>No room for a ball there: %1</source>
        <translation>Здесь нет места для шара: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="483" />
        <source>Add Plane</source>
        <translation>Добавить плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="497" />
        <source>Add Cylinder</source>
        <translation>Добавить цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="500" />
        <source>Cannot place it there: %1</source>
        <translation>Сюда поставить нельзя: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="486" />
        <source>Add Box</source>
        <translation>Добавить ящик</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="119" />
        <source>Resize Box</source>
        <translation>Изменить размер ящика</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_handles.cpp" line="110" />
        <source>Turn Box</source>
        <translation>Повернуть ящик</translation>
    </message>
</context>
<context>
    <name>carom::editor::OutlineDock</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="218" />
        <source>Outline</source>
        <translation>Структура</translation>
    </message>
</context>
<context>
    <name>carom::editor::OutlineModel</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="144" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="174" />
        <source>Rename</source>
        <translation>Переименовать</translation>
    </message>
</context>
<context>
    <name>carom::editor::PropertiesDock</name>
    <message>
        <location filename="../ui/editor/number_field.cpp" line="52" />
        <location filename="../ui/editor/properties_dock.cpp" line="380" />
        <location filename="../ui/editor/properties_dock.cpp" line="503" />
        <location filename="../ui/editor/properties_dock.cpp" line="540" />
        <location filename="../ui/editor/properties_dock.cpp" line="563" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="68" />
        <location filename="../ui/editor/properties_dock.cpp" line="314" />
        <location filename="../ui/editor/validation_text.cpp" line="41" />
        <source>m</source>
        <translation>м</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="69" />
        <location filename="../ui/editor/validation_text.cpp" line="49" />
        <source>m/s</source>
        <translation>м/с</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70" />
        <location filename="../ui/editor/validation_text.cpp" line="57" />
        <source>kg</source>
        <translation>кг</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="71" />
        <location filename="../ui/editor/validation_text.cpp" line="99" />
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="72" />
        <location filename="../ui/editor/validation_text.cpp" line="96" />
        <source>m/s²</source>
        <translation>м/с²</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="73" />
        <location filename="../ui/editor/properties_dock.cpp" line="334" />
        <source>(any length)</source>
        <translation>(любой длины)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="74" />
        <location filename="../ui/editor/validation_text.cpp" line="78" />
        <source>Name</source>
        <translation>Имя</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="74" />
        <source>Rename</source>
        <translation>Переименовать</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80" />
        <location filename="../ui/editor/validation_text.cpp" line="93" />
        <source>Colour</source>
        <translation>Цвет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80" />
        <source>Change Colour</source>
        <translation>Изменить цвет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="87" />
        <location filename="../ui/editor/validation_text.cpp" line="46" />
        <source>Position</source>
        <translation>Положение</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="87" />
        <location filename="../ui/editor/properties_dock.cpp" line="95" />
        <location filename="../ui/editor/properties_dock.cpp" line="113" />
        <source>Move</source>
        <translation>Переместить</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="89" />
        <location filename="../ui/editor/validation_text.cpp" line="48" />
        <source>Velocity</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="89" />
        <source>Change Velocity</source>
        <translation>Изменить скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="91" />
        <location filename="../ui/editor/properties_dock.cpp" line="109" />
        <location filename="../ui/editor/validation_text.cpp" line="54" />
        <source>Radius</source>
        <translation>Радиус</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="91" />
        <location filename="../ui/editor/properties_dock.cpp" line="109" />
        <source>Change Radius</source>
        <translation>Изменить радиус</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="93" />
        <location filename="../ui/editor/validation_text.cpp" line="56" />
        <source>Mass</source>
        <translation>Масса</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="93" />
        <source>Change Mass</source>
        <translation>Изменить массу</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="95" />
        <location filename="../ui/editor/validation_text.cpp" line="59" />
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101" />
        <location filename="../ui/editor/validation_text.cpp" line="61" />
        <source>Normal</source>
        <translation>Нормаль</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101" />
        <source>Turn Plane</source>
        <translation>Повернуть плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="105" />
        <location filename="../ui/editor/validation_text.cpp" line="63" />
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="105" />
        <source>Turn Cylinder</source>
        <translation>Повернуть цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="120" />
        <location filename="../ui/editor/validation_text.cpp" line="95" />
        <source>Gravity</source>
        <translation>Гравитация</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="120" />
        <source>Change Gravity</source>
        <translation>Изменить гравитацию</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="122" />
        <location filename="../ui/editor/validation_text.cpp" line="98" />
        <source>Time step</source>
        <translation>Шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="122" />
        <source>Change Time Step</source>
        <translation>Изменить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="124" />
        <location filename="../ui/editor/properties_dock.cpp" line="301" />
        <location filename="../ui/editor/validation_text.cpp" line="80" />
        <source>Restitution</source>
        <translation>Восстановление</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="124" />
        <location filename="../ui/editor/properties_dock.cpp" line="301" />
        <source>Change Restitution</source>
        <translation>Изменить коэффициент восстановления</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="126" />
        <source>Method</source>
        <translation>Метод</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="126" />
        <source>Change Method</source>
        <translation>Изменить метод</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="128" />
        <source>Integrator</source>
        <translation>Интегратор</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="128" />
        <source>Change Integrator</source>
        <translation>Изменить интегратор</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="165" />
        <source>Properties</source>
        <translation>Свойства</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="177" />
        <source>0 to 1; empty: the world's restitution</source>
        <translation>От 0 до 1; пусто — коэффициент мира</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="178" />
        <source>Between the caps; empty: infinite</source>
        <translation>Между торцами; пусто: бесконечный</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="183" />
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="184" />
        <source>Choose a colour</source>
        <translation>Выбрать цвет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="185" />
        <location filename="../ui/editor/properties_dock.cpp" line="580" />
        <source>Object Colour</source>
        <translation>Цвет объекта</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="313" />
        <location filename="../ui/editor/validation_text.cpp" line="65" />
        <source>Length</source>
        <translation>Длина</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="313" />
        <source>Resize Cylinder</source>
        <translation>Изменить длину цилиндра</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="326" />
        <location filename="../ui/editor/properties_dock.cpp" line="438" />
        <source>infinite</source>
        <translation>бесконечный</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="374" />
        <source>World (nothing selected)</source>
        <translation>Мир (ничего не выбрано)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="383" />
        <source>%1: %n selected</source>
        <translation>
            <numerusform>%1: выбран %n</numerusform>
            <numerusform>%1: выбрано %n</numerusform>
            <numerusform>%1: выбрано %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="386" />
        <source>%n objects selected</source>
        <translation>
            <numerusform>Выбран %n объект</numerusform>
            <numerusform>Выбрано %n объекта</numerusform>
            <numerusform>Выбрано %n объектов</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="396" />
        <source>mixed</source>
        <translation>разные</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="416" />
        <source>default</source>
        <translation>по умолчанию</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="430" />
        <source>world's (%1)</source>
        <translation>как у мира (%1)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="113" />
        <location filename="../ui/editor/validation_text.cpp" line="67" />
        <source>Centre</source>
        <translation>Центр</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="116" />
        <location filename="../ui/editor/validation_text.cpp" line="71" />
        <source>Half extents</source>
        <translation>Половины размеров</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="116" />
        <source>Resize Box</source>
        <translation>Изменить размер ящика</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="333" />
        <location filename="../ui/editor/validation_text.cpp" line="73" />
        <source>Rotation axis</source>
        <translation>Ось поворота</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="333" />
        <location filename="../ui/editor/properties_dock.cpp" line="343" />
        <source>Turn Box</source>
        <translation>Повернуть ящик</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="343" />
        <location filename="../ui/editor/validation_text.cpp" line="75" />
        <source>Rotation</source>
        <translation>Поворот</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="344" />
        <location filename="../ui/editor/validation_text.cpp" line="76" />
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="453" />
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="182" />
        <source>Degrees about the axis, right-handed; empty: not turned</source>
        <translation>Градусы вокруг оси, по правилу правой руки; пусто: без поворота</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="51" />
        <source>Angular velocity</source>
        <translation>Угловая скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="52" />
        <source>rad/s</source>
        <translation>рад/с</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="82" />
        <source>Friction</source>
        <translation>Трение</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="84" />
        <source>Rolling resistance</source>
        <translation>Сопротивление качению</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="87" />
        <source>Spinning friction</source>
        <translation>Трение верчения</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="90" />
        <source>Tangential restitution</source>
        <translation>Касательное восстановление</translation>
    </message>
</context>
<context>
    <name>carom::editor::SceneDocument</name>
    <message>
        <location filename="../ui/editor/scene_document.cpp" line="97" />
        <source>untitled</source>
        <translation>без имени</translation>
    </message>
    <message>
        <location filename="../ui/editor/scene_document.cpp" line="111" />
        <source>floor</source>
        <translation>пол</translation>
    </message>
</context>
<context>
    <name>carom::ui</name>
    <message>
        <location filename="../ui/watch_text.cpp" line="24" />
        <source>ball %1 (%2)</source>
        <translation>шар %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="25" />
        <source>ball %1</source>
        <translation>шар %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="39" />
        <source>plane %1</source>
        <translation>плоскость %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="41" />
        <source>cylinder %1</source>
        <translation>цилиндр %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="44" />
        <source>box %1</source>
        <translation>ящик %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="58" />
        <source>At %1 s %2 has a position or velocity that is not a finite number.</source>
        <translation>В %1 с у объекта «%2» положение или скорость — не конечное число.</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="61" />
        <source>At %1 s the energy rose by %2 of the scene's energy scale (tolerance %3); %4 gained the most.</source>
        <translation>В %1 с энергия выросла на %2 от масштаба энергии сцены (допуск %3); больше всего получил %4.</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="65" />
        <source>At %1 s %2 got inside %3: its centre is %4 of its radius past the surface.</source>
        <translation>В %1 с %2 оказался внутри объекта «%3»: его центр на %4 радиуса за поверхностью.</translation>
    </message>
    <message>
        <location filename="../ui/watch_text.cpp" line="68" />
        <source>At %1 s %2 overlaps %3 by %4 of the radius (tolerance %5).</source>
        <translation>В %1 с %2 перекрывается с %3 на %4 радиуса (допуск %5).</translation>
    </message>
</context>
<context>
    <name>carom::ui::AccuracyWindow</name>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="161" />
        <source>Speed vs accuracy</source>
        <translation>Скорость и точность</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="163" />
        <source>Position error against exact at the horizon (m)</source>
        <translation>Ошибка положения относительно exact на горизонте (м)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="164" />
        <source>Relative energy drift</source>
        <translation>Относительный дрейф энергии</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="165" />
        <source>Deepest penetration (m)</source>
        <translation>Максимальная глубина проникновения (м)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="166" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="403" />
        <source>Escaped balls</source>
        <translation>Вылетевшие шары</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="167" />
        <source>Speed distribution against exact (KS distance)</source>
        <translation>Распределение скоростей относительно exact (расстояние КС)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="168" />
        <source>Position distribution against exact (KS distance)</source>
        <translation>Распределение положений относительно exact (расстояние КС)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="169" />
        <source>Energy error per simulated second (auto's measure)</source>
        <translation>Ошибка энергии за секунду моделирования (мера auto)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="172" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <source>Computing time (s)</source>
        <translation>Время вычислений (с)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="173" />
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="174" />
        <source>Cheapest within the tolerance</source>
        <translation>Самый дешёвый в пределах допуска</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="175" />
        <source>Chosen run</source>
        <translation>Выбранный прогон</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <source>Run</source>
        <translation>Прогон</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <source>Position error at horizon (m)</source>
        <translation>Ошибка положения на горизонте (м)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="182" />
        <source>Each point is one run of the current scene; lower and further left is better. Choose a run to use its settings. Paths part from exact ones with time, whatever the method: position error is taken at the horizon up to which the finest setting agrees with exact, and whole runs are judged by energy, penetration, escapes and distributions.</source>
        <translation>Каждая точка — один прогон текущей сцены; чем ниже и левее, тем лучше. Выберите прогон, чтобы применить его настройки. Траектории со временем расходятся с точными при любом методе: ошибка положения берётся на горизонте, до которого самая точная настройка совпадает с exact, а прогоны целиком оцениваются по энергии, проникновению, вылетам и распределениям.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="317" />
        <source>position error at the horizon</source>
        <translation>ошибке положения на горизонте</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="318" />
        <source>at most %1 m, a tenth of the mean radius: as close as the finest setting stays to exact up to the horizon</source>
        <translation>не более %1 м, десятая часть среднего радиуса: так близко, как самая точная настройка держится к exact до горизонта</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="323" />
        <source>relative energy drift</source>
        <translation>относительному дрейфу энергии</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="324" />
        <source>at most %1: auto's energy error per second times the %2 s of the run</source>
        <translation>не более %1: ошибка энергии в секунду для auto, умноженная на %2 с прогона</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="328" />
        <source>deepest penetration</source>
        <translation>наибольшему проникновению</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="329" />
        <source>at most %1 m: auto's %2 % of the smallest radius</source>
        <translation>не более %1 м: %2 % наименьшего радиуса, как у auto</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="333" />
        <source>escaped balls</source>
        <translation>вылетевшим шарам</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="334" />
        <source>none, as auto asks</source>
        <translation>ни одного, как требует auto</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="339" />
        <source>speed distribution against exact</source>
        <translation>распределению скоростей относительно exact</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="340" />
        <source>position distribution against exact</source>
        <translation>распределению положений относительно exact</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/accuracy_window.cpp" line="341" />
        <source>a KS distance of at most %1: %Ln balls cannot tell it from exact's at 5 % significance</source>
        <translation>
            <numerusform>расстояние КС не более %1: по %Ln шару её не отличить от точной при значимости 5 %</numerusform>
            <numerusform>расстояние КС не более %1: по %Ln шарам её не отличить от точной при значимости 5 %</numerusform>
            <numerusform>расстояние КС не более %1: по %Ln шарам её не отличить от точной при значимости 5 %</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="347" />
        <source>energy error per simulated second</source>
        <translation>ошибке энергии за модельную секунду</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="348" />
        <source>at most %1 per second, auto's accuracy</source>
        <translation>не более %1 в секунду, точность auto</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="352" />
        <source>Tolerance on %1: %2. Ringed: the cheapest run within it.</source>
        <translation>Допуск по %1: %2. Обведён: самый дешёвый прогон в нём.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="402" />
        <source>Position error (m)</source>
        <translation>Ошибка положения (м)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="404" />
        <source>Speeds (KS distance)</source>
        <translation>Скорости (расстояние КС)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="404" />
        <source>Positions (KS distance)</source>
        <translation>Положения (расстояние КС)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="405" />
        <source>Energy error per second</source>
        <translation>Ошибка энергии в секунду</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="428" />
        <source>Each run: %1 s simulated</source>
        <translation>Каждый прогон: %1 с моделирования</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="432" />
        <source>%1; the finest setting agrees with exact up to %2 s</source>
        <translation>%1; самая точная настройка совпадает с exact до %2 с</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="435" />
        <source>%1; even the finest setting parts from exact at once: no position error</source>
        <translation>%1; даже самая точная настройка сразу расходится с exact: ошибки положения нет</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="177" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="402" />
        <source>Energy drift</source>
        <translation>Дрейф энергии</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <source>Escaped</source>
        <translation>Вылетело</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <location filename="../ui/dialogs/accuracy_window.cpp" line="403" />
        <source>Penetration (m)</source>
        <translation>Проникновение (м)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <source>Speeds (KS)</source>
        <translation>Скорости (КС)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="178" />
        <source>Positions (KS)</source>
        <translation>Положения (КС)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="179" />
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="180" />
        <source>Apply Selected Settings</source>
        <translation>Применить выбранные настройки</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/accuracy_window.cpp" line="272" />
        <source>%Ln runs</source>
        <translation>
            <numerusform>%Ln прогон</numerusform>
            <numerusform>%Ln прогона</numerusform>
            <numerusform>%Ln прогонов</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="278" />
        <source>Cancelled after %1 in %2 s.</source>
        <translation>Прервано после %1 за %2 с.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/accuracy_window.cpp" line="281" />
        <source>%Ln threads</source>
        <translation>
            <numerusform>%Ln поток</numerusform>
            <numerusform>%Ln потока</numerusform>
            <numerusform>%Ln потоков</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="287" />
        <source>%1 in %2 s on %3, no faster than one after another</source>
        <translation>%1 за %2 с на %3, не быстрее, чем по очереди</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="290" />
        <source>%1 in %2 s on %3, %4× faster than one after another</source>
        <translation>%1 за %2 с на %3, в %4 раза быстрее, чем по очереди</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/accuracy_window.cpp" line="162" />
        <source>Error:</source>
        <translation>Ошибка:</translation>
    </message>
</context>
<context>
    <name>carom::ui::AutoMethod</name>
    <message>
        <location filename="../ui/auto_method.cpp" line="24" />
        <source>%1 (%2, step %3 s)</source>
        <translation>%1 (%2, шаг %3 с)</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="102" />
        <source>Auto: no setting meets the accuracy; the settings are kept</source>
        <translation>Auto: ни одна настройка не даёт нужной точности; настройки оставлены</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="103" />
        <source>No setting meets an energy error of %1 per second; the closest is %2. The settings are kept.</source>
        <translation>Ни одна настройка не даёт ошибку энергии %1 в секунду; ближе всех %2. Настройки оставлены.</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="113" />
        <source>Auto: %1</source>
        <translation>Auto: %1</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="118" />
        <source>Auto chose %1</source>
        <translation>Auto выбрал %1</translation>
    </message>
    <message>
        <location filename="../ui/auto_method.cpp" line="119" />
        <source>Auto chose %1: the cheapest setting with an energy error under %2 per second (%3 s of computing per simulated second; pilot %4 s).</source>
        <translation>Auto выбрал %1: самая дешёвая настройка с ошибкой энергии меньше %2 в секунду (%3 с вычислений на секунду моделирования; пробный прогон %4 с).</translation>
    </message>
    <message>
        <source>Auto: no setting meets an energy error of %1 per second; the closest is %2. The settings are kept.</source>
        <translation type="vanished">Auto: ни одна настройка не даёт ошибку энергии %1 в секунду; ближе всех %2. Настройки оставлены.</translation>
    </message>
    <message>
        <source>Choose Method Automatically</source>
        <translation type="vanished">Выбрать метод автоматически</translation>
    </message>
    <message>
        <source>Auto chose %1: the cheapest setting with an energy error under %2 per second (%3 s of computing per simulated second; pilot %4 s)</source>
        <translation type="vanished">Auto выбрал %1: самая дешёвая настройка с ошибкой энергии меньше %2 в секунду (%3 с вычислений на секунду моделирования; пробный прогон %4 с)</translation>
    </message>
</context>
<context>
    <name>carom::ui::BallStoryDock</name>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="105" />
        <source>Ball Story</source>
        <translation>История шара</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="107" />
        <source>Height (m)</source>
        <translation>Высота (м)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="108" />
        <source>Speed (m/s)</source>
        <translation>Скорость (м/с)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="109" />
        <source>Energy (J)</source>
        <translation>Энергия (Дж)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="111" />
        <source>Height is measured against gravity (along y when there is none); energy is the ball's kinetic energy plus its potential energy relative to the origin.</source>
        <translation>Высота отсчитывается против силы тяжести (по y, если её нет); энергия — кинетическая энергия шара плюс его потенциальная энергия относительно начала координат.</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="115" />
        <source>Simulated time (s)</source>
        <translation>Модельное время (с)</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="122" />
        <source>Select balls to follow them: their story starts when they are selected.</source>
        <translation>Выберите шары, чтобы следить за ними: их история начинается с момента выбора.</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="124" />
        <source>Showing the first %1 of %2 selected balls; each story starts when the ball is selected.</source>
        <translation>Показаны первые %1 шаров из выбранных (%2); история каждого шара начинается с момента его выбора.</translation>
    </message>
    <message>
        <location filename="../ui/docks/ball_story_dock.cpp" line="129" />
        <source>Each ball's story starts when it is selected.</source>
        <translation>История каждого шара начинается с момента его выбора.</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditActions</name>
    <message>
        <location filename="../ui/edit_actions.cpp" line="34" />
        <source>clipboard</source>
        <translation>буфер обмена</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="36" />
        <source>Nothing to paste: %1</source>
        <translation>Нечего вставить: %1</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="39" />
        <source>Paste</source>
        <translation>Вставить</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="43" />
        <source>Duplicate</source>
        <translation>Дублировать</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="47" />
        <source>Delete</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <location filename="../ui/edit_actions.cpp" line="81" />
        <source>Cannot place the objects: %1</source>
        <translation>Не удаётся разместить объекты: %1</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditMenu</name>
    <message>
        <location filename="../ui/edit_menu.cpp" line="68" />
        <source>&amp;Edit</source>
        <translation>&amp;Правка</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="57" />
        <source>&amp;Undo %1</source>
        <translation>&amp;Отменить: %1</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="59" />
        <source>&amp;Redo %1</source>
        <translation>&amp;Повторить: %1</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="56" />
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="58" />
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="70" />
        <source>&amp;Copy</source>
        <translation>&amp;Копировать</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="71" />
        <source>&amp;Paste</source>
        <translation>В&amp;ставить</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="72" />
        <source>&amp;Duplicate</source>
        <translation>&amp;Дублировать</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="73" />
        <source>De&amp;lete</source>
        <translation>&amp;Удалить</translation>
    </message>
    <message>
        <location filename="../ui/edit_menu.cpp" line="74" />
        <source>Select &amp;All</source>
        <translation>Выделить &amp;всё</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditorToolBar</name>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Select</source>
        <translation>Выбор</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Add Ball</source>
        <translation>Добавить шар</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Add Plane</source>
        <translation>Добавить плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="76" />
        <source>Add Cylinder</source>
        <translation>Добавить цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="75" />
        <source>Tools</source>
        <translation>Инструменты</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="80" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="83" />
        <source>Snap to &amp;Grid</source>
        <translation>Привязка к &amp;сетке</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="85" />
        <source>Moves land on multiples of %1 m</source>
        <translation>Перемещения кратны %1 м</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="74" />
        <source>&amp;Tools</source>
        <translation>&amp;Инструменты</translation>
    </message>
    <message>
        <location filename="../ui/editor_tool_bar.cpp" line="77" />
        <source>Add Box</source>
        <translation>Добавить ящик</translation>
    </message>
</context>
<context>
    <name>carom::ui::EnergyPlot</name>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="67" />
        <source>Kinetic</source>
        <translation>Кинетическая</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="68" />
        <source>Potential</source>
        <translation>Потенциальная</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="69" />
        <source>Total</source>
        <translation>Полная</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="70" />
        <source>Simulated time (s)</source>
        <translation>Модельное время (с)</translation>
    </message>
    <message>
        <location filename="../ui/docks/energy_plot.cpp" line="71" />
        <source>Energy (J)</source>
        <translation>Энергия (Дж)</translation>
    </message>
</context>
<context>
    <name>carom::ui::ExamplesMenu</name>
    <message>
        <location filename="../ui/examples_menu.cpp" line="26" />
        <source>&amp;Examples</source>
        <translation>&amp;Примеры</translation>
    </message>
</context>
<context>
    <name>carom::ui::FileMenu</name>
    <message>
        <location filename="../ui/file_menu.cpp" line="64" />
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="67" />
        <source>Open &amp;Recent</source>
        <translation>&amp;Недавние файлы</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="65" />
        <source>&amp;New</source>
        <translation>&amp;Создать</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="66" />
        <source>&amp;Open…</source>
        <translation>&amp;Открыть…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="68" />
        <source>&amp;Save</source>
        <translation>Со&amp;хранить</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="69" />
        <source>Save &amp;As…</source>
        <translation>Сохранить &amp;как…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="70" />
        <source>Export &amp;Image…</source>
        <translation>Экспорт &amp;изображения…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="71" />
        <source>Export &amp;Video…</source>
        <translation>Экспорт ви&amp;део…</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="55" />
        <source>(none)</source>
        <translation>(нет)</translation>
    </message>
    <message>
        <location filename="../ui/file_menu.cpp" line="72" />
        <source>&amp;Quit</source>
        <translation>&amp;Выход</translation>
    </message>
</context>
<context>
    <name>carom::ui::GrabControl</name>
    <message>
        <location filename="../ui/grab_control.cpp" line="65" />
        <source>Throw Speed Limit</source>
        <translation>Предел скорости броска</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="66" />
        <source>Fastest throw of a grabbed ball (m/s):</source>
        <translation>Наибольшая скорость броска захваченного шара (м/с):</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="80" />
        <source>The grab stopped at t = %1 s: ball %2 would have been crushed against what is behind it.</source>
        <translation>Захват остановлен при t = %1 с: шар %2 был бы раздавлен о то, что за ним.</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="85" />
        <source>The grab stopped at t = %1 s: the balls in front are jammed.</source>
        <translation>Захват остановлен при t = %1 с: шары впереди заклинило.</translation>
    </message>
    <message>
        <location filename="../ui/grab_control.cpp" line="88" />
        <source>Thrown at the throw limit, %1 m/s (Simulation &gt; Throw Speed Limit).</source>
        <translation>Брошен с предельной скоростью %1 м/с (Симуляция &gt; Предел скорости броска).</translation>
    </message>
</context>
<context>
    <name>carom::ui::HelpMenu</name>
    <message>
        <location filename="../ui/help_menu.cpp" line="40" />
        <source>&amp;User Guide</source>
        <translation>&amp;Руководство пользователя</translation>
    </message>
    <message>
        <location filename="../ui/help_menu.cpp" line="38" />
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <location filename="../ui/help_menu.cpp" line="39" />
        <source>&amp;Keyboard and Mouse</source>
        <translation>&amp;Клавиатура и мышь</translation>
    </message>
    <message>
        <location filename="../ui/help_menu.cpp" line="41" />
        <source>&amp;About Carom</source>
        <translation>&amp;О программе Carom</translation>
    </message>
</context>
<context>
    <name>carom::ui::HelpWindow</name>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="72" />
        <source>Keyboard and Mouse</source>
        <translation>Клавиатура и мышь</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="77" />
        <source>User Guide</source>
        <translation>Руководство пользователя</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="78" />
        <source>Back</source>
        <translation>Назад</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="87" />
        <source>Simulation</source>
        <translation>Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="88" />
        <source>Run or pause the simulation</source>
        <translation>Запустить или приостановить симуляцию</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="89" />
        <source>Advance one time step, paused</source>
        <translation>Выполнить один шаг по времени и остановиться</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="90" />
        <source>Back to the scene's initial state, paused</source>
        <translation>Вернуть сцену в начальное состояние и остановиться</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="91" />
        <source>Larger time step (×1.25)</source>
        <translation>Увеличить шаг по времени (×1,25)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="92" />
        <source>Smaller time step (÷1.25)</source>
        <translation>Уменьшить шаг по времени (÷1,25)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="93" />
        <source>Up, Down, wheel over a toolbar box</source>
        <translation>Стрелки вверх и вниз, колесо мыши над полем панели инструментов</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="93" />
        <source>Change its value by a step</source>
        <translation>Изменить его значение на один шаг</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="94" />
        <source>Typing in a toolbar box, then Enter</source>
        <translation>Ввод в поле панели инструментов, затем Enter</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="94" />
        <source>Set the value exactly</source>
        <translation>Задать значение точно</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="95" />
        <source>Mute or unmute the collision sounds</source>
        <translation>Выключить или включить звуки столкновений</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="96" />
        <source>View</source>
        <translation>Вид</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="97" />
        <source>Left drag on empty space</source>
        <translation>Перетаскивание левой кнопкой по пустому месту</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="97" />
        <source>Orbit the camera round the scene</source>
        <translation>Вращать камеру вокруг сцены</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="98" />
        <source>Middle drag</source>
        <translation>Перетаскивание средней кнопкой</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="98" />
        <source>Pan the camera</source>
        <translation>Сдвигать камеру</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="99" />
        <source>Mouse wheel</source>
        <translation>Колесо мыши</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="99" />
        <source>Zoom</source>
        <translation>Приближать и отдалять</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="100" />
        <source>Arrow keys (in the view)</source>
        <translation>Клавиши со стрелками (в окне сцены)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="100" />
        <source>Rotate the camera</source>
        <translation>Поворачивать камеру</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="101" />
        <source>Frame the whole scene</source>
        <translation>Показать всю сцену</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="102" />
        <source>Follow the selected ball, or the first one; again to stop</source>
        <translation>Следить за выбранным шаром или за первым; повторное нажатие прекращает</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="103" />
        <source>Full screen on or off</source>
        <translation>Включить или выключить полноэкранный режим</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="104" />
        <source>Editing tools</source>
        <translation>Инструменты правки</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="105" />
        <source>Select: click to pick, drag to move</source>
        <translation>Выбор: щелчок выбирает, перетаскивание перемещает</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="106" />
        <source>Add Ball</source>
        <translation>Добавить шар</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="107" />
        <source>Add Plane</source>
        <translation>Добавить плоскость</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="108" />
        <source>Add Cylinder</source>
        <translation>Добавить цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="110" />
        <source>Click with an Add tool</source>
        <translation>Щелчок инструментом добавления</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="111" />
        <source>Place the object where the cursor points, on a surface or the ground</source>
        <translation>Поставить объект туда, куда указывает курсор: на поверхность или на пол</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="112" />
        <source>Selecting and moving</source>
        <translation>Выбор и перемещение</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="113" />
        <source>Click</source>
        <translation>Щелчок</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="113" />
        <source>Select the object under the cursor; on nothing, clear the selection</source>
        <translation>Выбрать объект под курсором; щелчок по пустому месту снимает выбор</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="114" />
        <source>Ctrl+click, Shift+click</source>
        <translation>Ctrl+щелчок, Shift+щелчок</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="114" />
        <source>Add the object to the selection or take it out</source>
        <translation>Добавить объект к выбранным или исключить его</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="115" />
        <source>Drag a selected object</source>
        <translation>Перетаскивание выбранного объекта</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="115" />
        <source>Move the selection in the plane facing the camera</source>
        <translation>Перемещать выбранное в плоскости, обращённой к камере</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="116" />
        <source>X, Y or Z held while dragging</source>
        <translation>X, Y или Z, удерживаемые при перетаскивании</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="116" />
        <source>Move along that axis only</source>
        <translation>Перемещать только вдоль этой оси</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="117" />
        <source>Drag the tip of the arrow</source>
        <translation>Перетаскивание конца стрелки</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="118" />
        <source>Change a ball's velocity, a plane's normal or a cylinder's axis</source>
        <translation>Изменить скорость шара, нормаль плоскости или ось цилиндра</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="119" />
        <source>Alt+drag from a ball</source>
        <translation>Alt+перетаскивание от шара</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="119" />
        <source>Draw the ball's velocity, also for a ball at rest</source>
        <translation>Задать скорость шара, в том числе покоящегося</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="120" />
        <source>Escape while dragging or grabbing</source>
        <translation>Esc при перетаскивании или захвате</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="121" />
        <source>Cancel the drag: everything as it was before the press</source>
        <translation>Отменить перетаскивание: всё как до нажатия</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="122" />
        <source>Running world</source>
        <translation>Идущий мир</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="123" />
        <source>Drag a ball once the run has begun</source>
        <translation>Перетащить шар, когда прогон начался</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="124" />
        <source>Grab it: it follows the cursor and pushes other balls; let go to throw it</source>
        <translation>Захватить его: он следует за курсором и толкает другие шары; отпустить — бросить</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="125" />
        <source>X, Y or Z held while grabbing</source>
        <translation>X, Y или Z, зажатые при захвате</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="125" />
        <source>Keep the grabbed ball on that axis</source>
        <translation>Держать захваченный шар на этой оси</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="126" />
        <source>Drag the timeline under the view</source>
        <translation>Перетащить временную шкалу под видом</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="127" />
        <source>Show an earlier moment; Run goes on from there and forgets the rest</source>
        <translation>Показать более ранний момент; «Запуск» продолжает оттуда и забывает остальное</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="128" />
        <source>Arrows, Page Up/Down, Home, End (on the timeline)</source>
        <translation>Стрелки, Page Up/Down, Home, End (на временной шкале)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="129" />
        <source>Step through the recorded frames</source>
        <translation>Перейти по записанным кадрам</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="130" />
        <source>Edit</source>
        <translation>Правка</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="131" />
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="132" />
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="133" />
        <source>Copy the selection (as scene text)</source>
        <translation>Копировать выбранное (как текст сцены)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="134" />
        <source>Paste objects, moved aside where they would overlap</source>
        <translation>Вставить объекты, сдвинув их, если они перекрываются</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="135" />
        <source>Duplicate the selection</source>
        <translation>Дублировать выбранное</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="136" />
        <source>Delete the selection</source>
        <translation>Удалить выбранное</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="137" />
        <source>Select every object</source>
        <translation>Выбрать все объекты</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="138" />
        <source>Files</source>
        <translation>Файлы</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="139" />
        <source>New scene</source>
        <translation>Новая сцена</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="140" />
        <source>Open a scene</source>
        <translation>Открыть сцену</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="141" />
        <source>Save</source>
        <translation>Сохранить</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="142" />
        <source>Save under another name</source>
        <translation>Сохранить под другим именем</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="143" />
        <source>Quit</source>
        <translation>Выйти</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="144" />
        <source>Dropping a file on the window</source>
        <translation>Перетаскивание файла в окно</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="144" />
        <source>Open it</source>
        <translation>Открыть его</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="145" />
        <source>Outline and Properties</source>
        <translation>Структура и свойства</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="146" />
        <source>Click, Ctrl+click, Shift+click</source>
        <translation>Щелчок, Ctrl+щелчок, Shift+щелчок</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="146" />
        <source>Select objects, as in the view</source>
        <translation>Выбирать объекты, как в окне сцены</translation>
    </message>
    <message>
        <source>Double-click, F2 (in the outline)</source>
        <translation type="vanished">Двойной щелчок, F2 (в структуре)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="147" />
        <source>Rename the object</source>
        <translation>Переименовать объект</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="147" />
        <source>Double-click (in the outline)</source>
        <translation>Двойной щелчок (в структуре)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="148" />
        <source>Enter, or leaving a field</source>
        <translation>Enter или переход из поля</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="148" />
        <source>Apply the typed value</source>
        <translation>Применить введённое значение</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="149" />
        <source>Speed vs Accuracy</source>
        <translation>Скорость и точность</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="150" />
        <source>Click a point</source>
        <translation>Щелчок по точке</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="150" />
        <source>Select its run in the table</source>
        <translation>Выбрать её прогон в таблице</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="151" />
        <source>Double-click a run</source>
        <translation>Двойной щелчок по прогону</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="151" />
        <source>Apply its settings to the scene</source>
        <translation>Применить его настройки к сцене</translation>
    </message>
    <message>
        <source>Physics Notes</source>
        <translation type="vanished">Заметки по физике</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/help_dialogs.cpp" line="109" />
        <source>Add Box</source>
        <translation>Добавить ящик</translation>
    </message>
</context>
<context>
    <name>carom::ui::HistoryDock</name>
    <message>
        <location filename="../ui/docks/history_dock.cpp" line="19" />
        <source>History</source>
        <translation>История</translation>
    </message>
</context>
<context>
    <name>carom::ui::ImageExport</name>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="114" />
        <source>Export Image</source>
        <translation>Экспорт изображения</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="115" />
        <source>PNG images (*.png)</source>
        <translation>Изображения PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="121" />
        <source>Cannot Export Image</source>
        <translation>Не удалось экспортировать изображение</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="124" />
        <source>Exported a %1×%2 image to %3</source>
        <translation>Изображение %1×%2 экспортировано в %3</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="140" />
        <source>The graphics driver could not draw a %1×%2 picture.</source>
        <translation>Графический драйвер не смог нарисовать изображение %1×%2.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="154" />
        <source>Could not write %1: %2</source>
        <translation>Не удалось записать %1: %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::ImageSizeDialog</name>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="41" />
        <source>Export Image</source>
        <translation>Экспорт изображения</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="51" />
        <source>Width (pixels)</source>
        <translation>Ширина (пикселей)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="52" />
        <source>Height (pixels)</source>
        <translation>Высота (пикселей)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="65" />
        <source>Width</source>
        <translation>Ширина</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="65" />
        <source>Height</source>
        <translation>Высота</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="69" />
        <source>%1: must be a whole number of pixels (got "%2")</source>
        <translation>%1: должно быть целым числом пикселей (получено «%2»)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/image_export.cpp" line="71" />
        <source>%1: must be between %2 and %3 pixels (got %4)</source>
        <translation>%1: должно быть от %2 до %3 пикселей (получено %4)</translation>
    </message>
</context>
<context>
    <name>carom::ui::LanguageMenu</name>
    <message>
        <location filename="../ui/language_menu.cpp" line="39" />
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
</context>
<context>
    <name>carom::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="233" />
        <source>Energy</source>
        <translation>Энергия</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="232" />
        <source>&amp;Follow Ball</source>
        <translation>&amp;Следить за шаром</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="260" />
        <source>%1[*] — Carom</source>
        <translation>%1[*] — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="287" />
        <source>Apply Settings</source>
        <translation>Применить настройки</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="128" />
        <source>The recovery copy could not be written (%1); the last one is kept. Save the scene elsewhere to be safe.</source>
        <translation>Не удалось записать резервную копию (%1); сохранена предыдущая. Для надёжности сохраните сцену в другом месте.</translation>
    </message>
    <message>
        <source>&amp;Physics Notes</source>
        <translation type="vanished">&amp;Заметки по физике</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="368" />
        <source>Use Current State as Initial</source>
        <translation>Сделать текущее состояние начальным</translation>
    </message>
</context>
<context>
    <name>carom::ui::NumberBox</name>
    <message>
        <location filename="../ui/number_box.cpp" line="31" />
        <source>must be finite (got %1)</source>
        <translation>должно быть конечным (получено %1)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="33" />
        <source>must be between %1 and %2 (got %3)</source>
        <translation>должно быть от %1 до %2 (получено %3)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="80" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::RunControls</name>
    <message>
        <location filename="../ui/run_controls.cpp" line="21" />
        <location filename="../ui/run_controls.cpp" line="72" />
        <source>&amp;Run</source>
        <translation>&amp;Запуск</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="73" />
        <source>Run or pause the simulation (Space)</source>
        <translation>Запустить или приостановить симуляцию (Пробел)</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="21" />
        <location filename="../ui/run_controls.cpp" line="72" />
        <source>&amp;Pause</source>
        <translation>&amp;Пауза</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="74" />
        <source>&amp;Step</source>
        <translation>&amp;Шаг</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="75" />
        <source>Advance one time step (S)</source>
        <translation>Выполнить один шаг по времени (S)</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="76" />
        <source>R&amp;eset</source>
        <translation>&amp;Сброс</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="77" />
        <source>Back to the scene's initial state (R)</source>
        <translation>Вернуть сцену в начальное состояние (R)</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="71" />
        <source>Simulation</source>
        <translation>Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="78" />
        <location filename="../ui/run_controls.cpp" line="79" />
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/run_controls.cpp" line="80" />
        <source>Simulated seconds per real second</source>
        <translation>Секунд модели за секунду реального времени</translation>
    </message>
</context>
<context>
    <name>carom::ui::SceneFiles</name>
    <message>
        <location filename="../ui/scene_files.cpp" line="29" />
        <source>Magic room</source>
        <translation>Волшебная комната</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="30" />
        <source>Galton board</source>
        <translation>Доска Гальтона</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="31" />
        <source>Gas box</source>
        <translation>Ящик с газом</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="32" />
        <source>Inelastic pile</source>
        <translation>Неупругая куча</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="33" />
        <source>Newton's cradle</source>
        <translation>Колыбель Ньютона</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="34" />
        <source>Staircase</source>
        <translation>Лестница</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="35" />
        <source>Marble run</source>
        <translation>Трасса для шариков</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="60" />
        <source>Open Scene</source>
        <translation>Открыть сцену</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="61" />
        <source>Carom scenes (*.carom *.json);;All files (*)</source>
        <translation>Сцены Carom (*.carom *.json);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="70" />
        <source>Cannot Open Scene</source>
        <translation>Не удаётся открыть сцену</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="114" />
        <source>“%1”</source>
        <translation>«%1»</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="115" />
        <source>an unsaved scene</source>
        <translation>несохранённая сцена</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="116" />
        <source>Recover Scene</source>
        <translation>Восстановление сцены</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="117" />
        <source>Carom did not close properly while %1 had unsaved changes. The copy saved at %2 can be recovered.</source>
        <translation>Carom завершился некорректно, когда в «%1» были несохранённые изменения. Копию, сохранённую %2, можно восстановить.</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="123" />
        <source>&amp;Recover</source>
        <translation>&amp;Восстановить</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="124" />
        <source>&amp;Discard</source>
        <translation>&amp;Отбросить</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="125" />
        <source>Not &amp;Now</source>
        <translation>Не &amp;сейчас</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="133" />
        <source>Cannot Recover Scene</source>
        <translation>Не удаётся восстановить сцену</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="157" />
        <source>Save Scene</source>
        <translation>Сохранить сцену</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="158" />
        <source>Carom scenes (*.carom);;All files (*)</source>
        <translation>Сцены Carom (*.carom);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="169" />
        <source>Cannot Save Scene</source>
        <translation>Не удаётся сохранить сцену</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="174" />
        <source>Saved %1</source>
        <translation>Сохранено: %1</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="182" />
        <source>Unsaved Changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <location filename="../ui/scene_files.cpp" line="183" />
        <source>The scene %1 has unsaved changes. Save them?</source>
        <translation>В сцене %1 есть несохранённые изменения. Сохранить их?</translation>
    </message>
</context>
<context>
    <name>carom::ui::SimulationMenu</name>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="54" />
        <source>&amp;Simulation</source>
        <translation>&amp;Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="55" />
        <source>Speed vs &amp;Accuracy…</source>
        <translation>Скорость и &amp;точность…</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="56" />
        <source>&amp;Throw Speed Limit…</source>
        <translation>Пр&amp;едел скорости броска…</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="57" />
        <source>Timeline &amp;Memory…</source>
        <translation>Па&amp;мять временной шкалы…</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="58" />
        <source>&amp;Use Current State as Initial</source>
        <translation>&amp;Сделать текущее состояние начальным</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="59" />
        <source>Edits Apply to the &amp;Running State</source>
        <translation>Правки применяются к &amp;идущей симуляции</translation>
    </message>
    <message>
        <location filename="../ui/simulation_menu.cpp" line="61" />
        <source>Off: an edit restarts the simulation from the edited scene. On: balls the edit leaves alone keep their running state.</source>
        <translation>Выключено: правка перезапускает симуляцию с изменённой сцены. Включено: шары, которых правка не касается, сохраняют текущее состояние.</translation>
    </message>
</context>
<context>
    <name>carom::ui::SimulationSync</name>
    <message>
        <location filename="../ui/simulation_sync.cpp" line="73" />
        <source>The edit does not fit the running state (%1): restarted from the edited scene.</source>
        <translation>Правка не согласуется с идущей симуляцией (%1): перезапуск с изменённой сцены.</translation>
    </message>
</context>
<context>
    <name>carom::ui::StatusReadout</name>
    <message numerus="yes">
        <location filename="../ui/status_readout.cpp" line="81" />
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %n balls   E = %5 J (drift %6)</source>
        <translation>
            <numerusform>t = %1 с   ×%2 от реального времени   %3 кадр/с   столкновений/с: %4   %n шар   E = %5 Дж (дрейф %6)</numerusform>
            <numerusform>t = %1 с   ×%2 от реального времени   %3 кадр/с   столкновений/с: %4   %n шара   E = %5 Дж (дрейф %6)</numerusform>
            <numerusform>t = %1 с   ×%2 от реального времени   %3 кадр/с   столкновений/с: %4   %n шаров   E = %5 Дж (дрейф %6)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/status_readout.cpp" line="89" />
        <source>   sound unavailable</source>
        <translation>   звук недоступен</translation>
    </message>
    <message>
        <location filename="../ui/status_readout.cpp" line="91" />
        <source>   muted</source>
        <translation>   звук выключен</translation>
    </message>
    <message>
        <location filename="../ui/status_readout.cpp" line="92" />
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — физика не успевает; замедленный ход</translation>
    </message>
</context>
<context>
    <name>carom::ui::TimelineBar</name>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="72" />
        <source>Timeline Memory</source>
        <translation>Память временной шкалы</translation>
    </message>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="72" />
        <source>Memory for the recorded run (MiB):</source>
        <translation>Память для записанного прогона (МиБ):</translation>
    </message>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="86" />
        <source>The recorded run: drag back to see an earlier moment; Run goes on from the moment shown and forgets what came after it.</source>
        <translation>Записанный прогон: потяните назад, чтобы увидеть более ранний момент; «Запуск» продолжает с показанного момента и забывает то, что было после него.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/timeline_bar.cpp" line="98" />
        <source>t = %1 s · frame %2 of %3 · %4 MiB in %n keyframes</source>
        <translation>
            <numerusform>t = %1 с · кадр %2 из %3 · %4 МиБ в %n ключевом кадре</numerusform>
            <numerusform>t = %1 с · кадр %2 из %3 · %4 МиБ в %n ключевых кадрах</numerusform>
            <numerusform>t = %1 с · кадр %2 из %3 · %4 МиБ в %n ключевых кадрах</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/timeline_bar.cpp" line="103" />
        <source>replayed in %1 ms</source>
        <translation>воспроизведено за %1 мс</translation>
    </message>
</context>
<context>
    <name>carom::ui::VideoExport</name>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="196" />
        <source>Start: must not be before 0 s (got %1 s)</source>
        <translation>Начало: должно быть не раньше 0 с (получено %1 с)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="198" />
        <source>End: must not be before the start, %1 s (got %2 s)</source>
        <translation>Конец: должен быть не раньше начала, %1 с (получено %2 с)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="201" />
        <source>End: the run is recorded up to %1 s only (got %2 s)</source>
        <translation>Конец: прогон записан только до %1 с (получено %2 с)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="204" />
        <source>Frames per second: must be a whole number from %1 to %2 (got "%3")</source>
        <translation>Кадров в секунду: должно быть целым числом от %1 до %2 (получено «%3»)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="214" />
        <source>MP4 needs ffmpeg, which was not found on the PATH: choose PNG images, or install ffmpeg.</source>
        <translation>Для MP4 нужен ffmpeg, но в PATH его нет: выберите изображения PNG или установите ffmpeg.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="219" />
        <source>MP4: the width and height must be even (got %1×%2)</source>
        <translation>MP4: ширина и высота должны быть чётными (получено %1×%2)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="255" />
        <location filename="../ui/dialogs/video_export.cpp" line="355" />
        <source>Export Video</source>
        <translation>Экспорт видео</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="256" />
        <source>MP4 videos (*.mp4)</source>
        <translation>Видео MP4 (*.mp4)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="263" />
        <source>Export Video: Folder for the Frames</source>
        <translation>Экспорт видео: папка для кадров</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="270" />
        <location filename="../ui/dialogs/video_export.cpp" line="478" />
        <source>Cannot Export Video</source>
        <translation>Не удалось экспортировать видео</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="281" />
        <source>A video is being exported already.</source>
        <translation>Видео уже экспортируется.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="284" />
        <source>There is no run to export yet.</source>
        <translation>Ещё нет прогона для экспорта.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="289" />
        <source>No folder or file was chosen.</source>
        <translation>Не выбраны ни папка, ни файл.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="292" />
        <source>Could not create the folder %1.</source>
        <translation>Не удалось создать папку %1.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="294" />
        <source>Could not write into the folder %1.</source>
        <translation>Не удалось записать в папку %1.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="297" />
        <source>The folder %1 already holds frames (frame_*.png): choose another folder or remove them first.</source>
        <translation>В папке %1 уже есть кадры (frame_*.png): выберите другую папку или сначала удалите их.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="303" />
        <source>Could not write %1: its folder does not exist or cannot be written.</source>
        <translation>Не удалось записать %1: папка не существует или недоступна для записи.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="306" />
        <source>Could not write %1: it is a folder.</source>
        <translation>Не удалось записать %1: это папка.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="343" />
        <source>Could not start ffmpeg: %1</source>
        <translation>Не удалось запустить ffmpeg: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="352" />
        <source>Exporting %n video frame(s)…</source>
        <translation>
            <numerusform>Экспорт %n кадра видео…</numerusform>
            <numerusform>Экспорт %n кадров видео…</numerusform>
            <numerusform>Экспорт %n кадров видео…</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="352" />
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="380" />
        <source>The run was reset or went on from an earlier frame during the export, which stopped after %n frame(s).</source>
        <translation>
            <numerusform>Во время экспорта прогон был сброшен или продолжен с более раннего кадра; экспорт остановлен после %n кадра.</numerusform>
            <numerusform>Во время экспорта прогон был сброшен или продолжен с более раннего кадра; экспорт остановлен после %n кадров.</numerusform>
            <numerusform>Во время экспорта прогон был сброшен или продолжен с более раннего кадра; экспорт остановлен после %n кадров.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="400" />
        <source>Finishing the video…</source>
        <translation>Завершение видео…</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="424" />
        <source>The graphics driver could not draw a %1×%2 picture.</source>
        <translation>Графический драйвер не смог нарисовать изображение %1×%2.</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation type="vanished">Не удалось записать %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="454" />
        <source>ffmpeg failed (exit code %1): %2</source>
        <translation>Ошибка ffmpeg (код выхода %1): %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="458" />
        <source>Exported %n video frame(s) of %1×%2 at %3 fps to %4</source>
        <translation>
            <numerusform>Экспортирован %n кадр видео %1×%2 при %3 fps в %4</numerusform>
            <numerusform>Экспортировано %n кадра видео %1×%2 при %3 fps в %4</numerusform>
            <numerusform>Экспортировано %n кадров видео %1×%2 при %3 fps в %4</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="472" />
        <source>The %n frame(s) written before were left in %1.</source>
        <translation>
            <numerusform>%n уже записанный кадр оставлен в %1.</numerusform>
            <numerusform>%n уже записанных кадра оставлены в %1.</numerusform>
            <numerusform>%n уже записанных кадров оставлены в %1.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="490" />
        <source>Video export cancelled; the unfinished video was removed.</source>
        <translation>Экспорт видео отменён; незаконченное видео удалено.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/dialogs/video_export.cpp" line="491" />
        <source>Video export cancelled after %n frame(s); they were left in %1.</source>
        <translation>
            <numerusform>Экспорт видео отменён после %n кадра; он оставлен в %1.</numerusform>
            <numerusform>Экспорт видео отменён после %n кадров; они оставлены в %1.</numerusform>
            <numerusform>Экспорт видео отменён после %n кадров; они оставлены в %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>carom::ui::VideoExportDialog</name>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="79" />
        <source>Export Video</source>
        <translation>Экспорт видео</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="91" />
        <source>PNG images in a folder</source>
        <translation>Изображения PNG в папке</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="92" />
        <source>MP4 video (ffmpeg)</source>
        <translation>Видео MP4 (ffmpeg)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="94" />
        <source>The run is recorded from 0 to %1 s. Each video frame shows the recorded step that ended at its moment or last before it.</source>
        <translation>Прогон записан от 0 до %1 с. Каждый кадр видео показывает записанный шаг, закончившийся в его момент или последним перед ним.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="106" />
        <source>MP4 needs ffmpeg, which was not found on the PATH (scripts/setup-debian.sh installs it); PNG images need nothing more.</source>
        <translation>Для MP4 нужен ffmpeg, но в PATH его нет (его устанавливает scripts/setup-debian.sh); для изображений PNG больше ничего не нужно.</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="116" />
        <source>Start (s)</source>
        <translation>Начало (с)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="117" />
        <source>End (s)</source>
        <translation>Конец (с)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="118" />
        <source>Frames per second</source>
        <translation>Кадров в секунду</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="119" />
        <source>Width (pixels)</source>
        <translation>Ширина (пикселей)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="120" />
        <source>Height (pixels)</source>
        <translation>Высота (пикселей)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="121" />
        <source>Format</source>
        <translation>Формат</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="139" />
        <source>Start: must be a number of seconds (got "%1")</source>
        <translation>Начало: должно быть числом секунд (получено «%1»)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="140" />
        <source>End: must be a number of seconds (got "%1")</source>
        <translation>Конец: должен быть числом секунд (получено «%1»)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/video_export.cpp" line="142" />
        <source>Frames per second: must be a whole number from %1 to %2 (got "%3")</source>
        <translation>Кадров в секунду: должно быть целым числом от %1 до %2 (получено «%3»)</translation>
    </message>
</context>
<context>
    <name>carom::ui::ViewMenu</name>
    <message>
        <location filename="../ui/view_menu.cpp" line="72" />
        <source>&amp;Full Screen</source>
        <translation>&amp;Полноэкранный режим</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="73" />
        <source>&amp;Explosions</source>
        <translation>&amp;Взрывы</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="74" />
        <source>&amp;Antialiasing</source>
        <translation>&amp;Сглаживание</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="75" />
        <source>&amp;Mute</source>
        <translation>Без &amp;звука</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="71" />
        <source>F&amp;rame Scene</source>
        <translation>Показать всю с&amp;цену</translation>
    </message>
    <message>
        <location filename="../ui/view_menu.cpp" line="70" />
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
</context>
<context>
    <name>carom::ui::WatchAlert</name>
    <message>
        <location filename="../ui/watch_alert.cpp" line="36" />
        <source>Stopped by the watch: %1</source>
        <translation>Остановлено наблюдением: %1</translation>
    </message>
    <message>
        <location filename="../ui/watch_alert.cpp" line="51" />
        <source>Simulation Stopped</source>
        <translation>Симуляция остановлена</translation>
    </message>
    <message>
        <location filename="../ui/watch_alert.cpp" line="55" />
        <source>The run is paused. The last step that passed the watch ended at %1 s. The checks and their tolerances are in Simulation &gt; Watch.</source>
        <translation>Прогон приостановлен. Последний шаг, прошедший проверку, закончился в %1 с. Проверки и их допуски — в меню Симуляция &gt; Наблюдение.</translation>
    </message>
    <message>
        <location filename="../ui/watch_alert.cpp" line="62" />
        <source>Show the Moment Before</source>
        <translation>Показать момент перед этим</translation>
    </message>
</context>
<context>
    <name>carom::ui::WatchMenu</name>
    <message>
        <location filename="../ui/watch_menu.cpp" line="105" />
        <source>&amp;Watch</source>
        <translation>&amp;Наблюдение</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="107" />
        <source>Stop on &amp;Non-finite Numbers</source>
        <translation>Останавливать при &amp;не конечных числах</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="108" />
        <source>Stop on &amp;Energy Rise</source>
        <translation>Останавливать при &amp;росте энергии</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="110" />
        <source>Only where no restitution exceeds 1, so that energy can only fall</source>
        <translation>Только если ни один коэффициент восстановления не больше 1, так что энергия может лишь убывать</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="111" />
        <source>Stop on Escape Through a &amp;Solid</source>
        <translation>Останавливать при уходе сквозь &amp;тело</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="112" />
        <source>Stop on Deep &amp;Penetration</source>
        <translation>Останавливать при глубоком &amp;проникновении</translation>
    </message>
    <message>
        <location filename="../ui/watch_menu.cpp" line="113" />
        <source>&amp;Tolerances…</source>
        <translation>&amp;Допуски…</translation>
    </message>
</context>
<context>
    <name>carom::ui::WatchToleranceDialog</name>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="15" />
        <source>Watch Tolerances</source>
        <translation>Допуски наблюдения</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="27" />
        <source>Energy rise</source>
        <translation>Рост энергии</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="29" />
        <source>How far the total energy may rise above its value at the start, as a fraction of the scene's energy scale (kinetic energy plus the balls' weight times the scene's height)</source>
        <translation>Насколько полная энергия может превысить начальную, в долях масштаба энергии сцены (кинетическая энергия плюс вес шаров, умноженный на высоту сцены)</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="32" />
        <source>Escape depth</source>
        <translation>Глубина ухода</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="34" />
        <source>How far a ball's centre may be past a solid's surface, as a fraction of its radius</source>
        <translation>Насколько центр шара может зайти за поверхность тела, в долях его радиуса</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="35" />
        <source>Penetration</source>
        <translation>Проникновение</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="36" />
        <source>How deep an overlap may be, as a fraction of the smaller radius</source>
        <translation>Насколько глубоким может быть перекрытие, в долях меньшего радиуса</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="39" />
        <source>Energy rise:</source>
        <translation>Рост энергии:</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="40" />
        <source>Escape depth:</source>
        <translation>Глубина ухода:</translation>
    </message>
    <message>
        <location filename="../ui/dialogs/watch_tolerance_dialog.cpp" line="41" />
        <source>Penetration:</source>
        <translation>Проникновение:</translation>
    </message>
</context>
<context>
    <name>carom::ui::WorldToolBar</name>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="167" />
        <source>Gravity</source>
        <translation>Гравитация</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="170" />
        <source>Gravity %1</source>
        <translation>Гравитация %1</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="171" />
        <source>Gravity %1 (m/s²)</source>
        <translation>Гравитация %1 (м/с²)</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="62" />
        <source>Change Gravity</source>
        <translation>Изменить гравитацию</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="103" />
        <source>Change Accuracy</source>
        <translation>Изменить точность</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="173" />
        <source>Step</source>
        <translation>Шаг</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="174" />
        <source>Time step</source>
        <translation>Шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="175" />
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Шаг по времени в секундах (клавиши + и -)</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="28" />
        <source>Change Time Step</source>
        <translation>Изменить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="85" />
        <location filename="../ui/world_tool_bar.cpp" line="89" />
        <source>Change Method</source>
        <translation>Изменить метод</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="182" />
        <source>Integrator of the swept and discrete methods</source>
        <translation>Интегратор для методов swept и discrete</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="35" />
        <source>Change Integrator</source>
        <translation>Изменить интегратор</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="76" />
        <source>Auto: piloting the scene under 13 settings…</source>
        <translation>Auto: пробный прогон сцены с 13 настройками…</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="166" />
        <source>World</source>
        <translation>Мир</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="154" />
        <source>Exact (event-driven), swept, or discrete steps; auto: the cheapest that meets the accuracy, found by a short pilot</source>
        <translation>Точный (по событиям), заметающие или дискретные шаги; auto: самый дешёвый из дающих нужную точность, по короткому пробному прогону</translation>
    </message>
    <message>
        <location filename="../ui/editor/validation_text.cpp" line="101" />
        <location filename="../ui/world_tool_bar.cpp" line="177" />
        <location filename="../ui/world_tool_bar.cpp" line="178" />
        <source>Accuracy</source>
        <translation>Точность</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="180" />
        <source>Auto's tolerance: the relative energy error per simulated second (and a penetration of at most 5% of the radius)</source>
        <translation>Допуск auto: относительная ошибка энергии за секунду моделирования (и проникновение не более 5% радиуса)</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="183" />
        <source>Larger Time Step</source>
        <translation>Увеличить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/world_tool_bar.cpp" line="184" />
        <source>Smaller Time Step</source>
        <translation>Уменьшить шаг по времени</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/window_arguments.cpp" line="32" />
        <source>Collision physics sandbox</source>
        <translation>Песочница для физики столкновений</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="35" />
        <source>Scene file to open</source>
        <translation>Файл сцены для открытия</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="38" />
        <source>Save a picture of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="39" />
        <source>file.png</source>
        <translation>файл.png</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="41" />
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Сколько секунд выполнять симуляцию перед --screenshot.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="42" />
        <source>seconds</source>
        <translation>секунды</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="43" />
        <source>Language of the program (en, ru, de).</source>
        <translation>Язык программы (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="44" />
        <source>code</source>
        <translation>код</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="46" />
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Запустить газ из N шаров на 5 с при виде 1280x720, вывести время кадров и самую долгую задержку интерфейса и выйти.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="51" />
        <source>Run a gas at about 10,000 collisions a second with explosions and sound for S seconds, print the collision rate, frame rate, GUI stalls and memory every 10 s, and quit.</source>
        <translation>Запустить газ примерно с 10 000 столкновений в секунду со взрывами и звуком на S секунд, каждые 10 с выводить частоту столкновений, частоту кадров, задержки GUI и память, затем выйти.</translation>
    </message>
    <message>
        <location filename="../app/window_arguments.cpp" line="57" />
        <source>Open the scene file, run it for 5 s, select its last ball in the outline, print how long each took, and quit.</source>
        <translation>Открыть файл сцены, запустить её на 5 с, выбрать последний шар в структуре, вывести, сколько заняло каждое действие, и выйти.</translation>
    </message>
</context>
</TS>
